#include "output/gltf_writer.hpp"

#include <tiny_gltf.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "output/png_writer.hpp"

namespace bookspin::output {
namespace {

constexpr int kArrayBuffer = 34962;         // GL_ARRAY_BUFFER
constexpr int kElementArrayBuffer = 34963;  // GL_ELEMENT_ARRAY_BUFFER

/// Builds the model's one buffer and its views and accessors.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

  /// A buffer view over `bytes` bytes copied from `data` (4-byte aligned); returns its index.
  int view(const void* data, std::size_t bytes, int target) {
    auto& buffer = model_.buffers[0].data;
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    if (target != 0) view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), begin, begin + bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  /// A float accessor of `rows`-component elements over the columns of `m` (rows × N).
  template <typename Matrix>
  int floats(const Matrix& m, int type, int target, bool with_bounds) {
    const Eigen::MatrixXf packed = m.template cast<float>();  // column-major: one element a column
    tinygltf::Accessor a;
    a.bufferView =
        view(packed.data(), sizeof(float) * static_cast<std::size_t>(packed.size()), target);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = static_cast<std::size_t>(packed.cols());
    a.type = type;
    if (with_bounds) {
      for (int r = 0; r < packed.rows(); ++r) {
        a.minValues.push_back(packed.row(r).minCoeff());
        a.maxValues.push_back(packed.row(r).maxCoeff());
      }
    }
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  int indices(const std::vector<std::uint32_t>& values) {
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), sizeof(std::uint32_t) * values.size(), kElementArrayBuffer);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.count = values.size();
    a.type = TINYGLTF_TYPE_SCALAR;
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

 private:
  tinygltf::Model& model_;
};

void validate(const std::vector<GltfPart>& parts, const GltfAnimation& animation) {
  if (parts.empty()) throw std::invalid_argument("write_glb: no part");
  for (const GltfPart& p : parts) {
    const auto v = p.positions.cols();
    if (v == 0 || p.indices.empty() || p.indices.size() % 3 != 0)
      throw std::invalid_argument("write_glb: part '" + p.name + "' has no triangles");
    if ((p.normals.cols() != 0 && p.normals.cols() != v) ||
        (p.uvs.cols() != 0 && p.uvs.cols() != v))
      throw std::invalid_argument("write_glb: part '" + p.name + "': attribute sizes differ");
    if (!p.positions.allFinite() || !p.normals.allFinite() || !p.uvs.allFinite())
      throw std::invalid_argument("write_glb: part '" + p.name + "' is not finite");
    for (const std::uint32_t i : p.indices)
      if (i >= v)
        throw std::invalid_argument("write_glb: part '" + p.name + "': index out of range");
    if (p.texture.width > 0 && p.uvs.cols() == 0)
      throw std::invalid_argument("write_glb: part '" + p.name + "' has a texture but no uvs");
  }
  const auto k = static_cast<Eigen::Index>(animation.times.size());
  if (k == 0 || animation.rotations.cols() != k || animation.translations.cols() != k)
    throw std::invalid_argument("write_glb: animation sizes differ");
  if (!animation.rotations.allFinite() || !animation.translations.allFinite())
    throw std::invalid_argument("write_glb: animation is not finite");
  for (Eigen::Index i = 1; i < k; ++i) {
    if (!(animation.times[i] > animation.times[i - 1]))
      throw std::invalid_argument("write_glb: animation times do not increase");
  }
}

}  // namespace

void write_glb(const std::filesystem::path& path, const std::string& name,
               const std::vector<GltfPart>& parts, const GltfAnimation& animation,
               const std::function<void()>& before_commit) {
  validate(parts, animation);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "bookspin";
  BufferBuilder buffers(model);

  tinygltf::Mesh mesh;
  mesh.name = name;
  for (const GltfPart& part : parts) {
    tinygltf::Material material;
    material.name = part.name;
    material.pbrMetallicRoughness.baseColorFactor = {part.colour.x(), part.colour.y(),
                                                     part.colour.z(), 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    if (part.texture.width > 0) {
      const std::vector<std::uint8_t> png = encode_png(part.texture, 6);
      tinygltf::Image image;
      image.name = part.name;
      image.mimeType = "image/png";
      image.bufferView = buffers.view(png.data(), png.size(), 0);
      model.images.push_back(image);
      if (model.samplers.empty()) {
        tinygltf::Sampler sampler;
        sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
        sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        model.samplers.push_back(sampler);
      }
      tinygltf::Texture texture;
      texture.sampler = 0;
      texture.source = static_cast<int>(model.images.size()) - 1;
      model.textures.push_back(texture);
      material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
      material.pbrMetallicRoughness.baseColorTexture.index =
          static_cast<int>(model.textures.size()) - 1;
    }
    model.materials.push_back(material);

    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = static_cast<int>(model.materials.size()) - 1;
    primitive.attributes["POSITION"] =
        buffers.floats(part.positions, TINYGLTF_TYPE_VEC3, kArrayBuffer, true);
    if (part.normals.cols() > 0)
      primitive.attributes["NORMAL"] =
          buffers.floats(part.normals, TINYGLTF_TYPE_VEC3, kArrayBuffer, false);
    if (part.uvs.cols() > 0)
      primitive.attributes["TEXCOORD_0"] =
          buffers.floats(part.uvs, TINYGLTF_TYPE_VEC2, kArrayBuffer, false);
    primitive.indices = buffers.indices(part.indices);
    mesh.primitives.push_back(primitive);
  }
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = name;
  node.mesh = 0;
  // Frame 0's pose, for viewers that show the model without playing the animation.
  const Eigen::Vector4f& q0 = animation.rotations.col(0);
  node.rotation = {q0.x(), q0.y(), q0.z(), q0.w()};
  node.translation = {animation.translations(0, 0), animation.translations(1, 0),
                      animation.translations(2, 0)};
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.name = name;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  tinygltf::Animation motion;
  motion.name = name;
  const Eigen::Map<const Eigen::RowVectorXf> times(
      animation.times.data(), static_cast<Eigen::Index>(animation.times.size()));
  const int input = buffers.floats(times, TINYGLTF_TYPE_SCALAR, 0, true);  // min/max required
  const int rotations = buffers.floats(animation.rotations, TINYGLTF_TYPE_VEC4, 0, false);
  const int translations = buffers.floats(animation.translations, TINYGLTF_TYPE_VEC3, 0, false);
  for (const auto& [output, target] :
       {std::pair{rotations, "rotation"}, std::pair{translations, "translation"}}) {
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = output;
    sampler.interpolation = "LINEAR";
    motion.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(motion.samplers.size()) - 1;
    channel.target_node = 0;
    channel.target_path = target;
    motion.channels.push_back(channel);
  }
  model.animations.push_back(motion);
  model.buffers[0].name = name;

  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, false, true))
    throw_output_error("cannot write glTF", path, "tinygltf refused the model");
  AtomicFile output(path);
  {
    std::ofstream file(output.temp_path(), std::ios::binary);
    if (!file) throw_output_error("cannot create glTF", path, errno);
    const std::string data = bytes.str();
    file.write(data.data(), static_cast<std::streamsize>(data.size()));
    file.close();
    if (!file) throw_output_error("cannot write glTF", path, errno);
  }
  if (before_commit) before_commit();
  output.commit();
}

}  // namespace bookspin::output
