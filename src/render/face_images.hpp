#pragma once
// The four images on the book's faces, as CPU images: generated with cairo or read from PNG.
#include <array>
#include <string>

#include "common/rgba_image.hpp"
#include "render/book_faces.hpp"

namespace bookspin::render {

/// The default image for `which` (see book_faces.hpp for how it lies on the faces):
/// front: dark blue cloth, gold border, "Classical Mechanics", subtitle and authors;
/// back: burgundy, blurb and a barcode box; spine: title along its long side;
/// pages: cream with fine page lines along its rows, cover-board bands at top and bottom.
/// Opaque RGBA, top row first. Its text is the typeface stage's built-in DejaVu
/// (typeface.hpp): the same pixels on every machine.
RgbaImage generate_face_image(FaceImage which);

/// Reads a PNG for a face (alpha is flattened onto white, the book is opaque). Throws
/// RenderError naming `face` and `path` if the file is missing or not a readable PNG.
RgbaImage load_face_image(const std::string& path, const char* face);

/// The four face images, indexed by FaceImage.
using FaceImages = std::array<RgbaImage, 4>;

/// For each face image: the PNG at the given path, or the generated default if the path is
/// empty (front, back, spine, pages in FaceImage order). Throws as the two functions above.
FaceImages face_images(const std::string& front, const std::string& back, const std::string& spine,
                       const std::string& pages);

}  // namespace bookspin::render
