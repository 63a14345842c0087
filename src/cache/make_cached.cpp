#include "cache/make_cached.hpp"

#include <algorithm>
#include <optional>
#include <set>

#include "cache/manifest_head.hpp"
#include "common/errors.hpp"
#include "common/stop.hpp"
#include "output/atomic_output.hpp"
#include "output/manifest.hpp"

namespace bookspin::cache {

namespace fs = std::filesystem;

namespace {

/// Removes the files an earlier run listed in its manifest (`earlier`, relative to OUT) that
/// this run (`now`) did not make, e.g. the GIF of a run with another render.formats, and the
/// folders that leaves empty: OUT holds the outputs of one run only (docs/outputs.md). Only
/// plain relative paths inside OUT are touched; errors are ignored (an output left behind is
/// no longer listed, so nothing links it).
void remove_outputs_of_earlier_run(const fs::path& out_dir, const std::vector<std::string>& earlier,
                                   const std::vector<std::string>& now) {
  const std::set<std::string> kept(now.begin(), now.end());
  std::set<fs::path> folders;
  for (const std::string& listed : earlier) {
    const fs::path relative(listed);
    if (kept.count(listed) != 0 || relative.empty() || relative.is_absolute() ||
        relative.lexically_normal() != relative ||
        std::find(relative.begin(), relative.end(), "..") != relative.end())
      continue;
    std::error_code ec;
    const fs::path file = out_dir / relative;
    if (!fs::is_regular_file(fs::symlink_status(file, ec)) || !fs::remove(file, ec)) continue;
    for (fs::path folder = relative.parent_path(); !folder.empty(); folder = folder.parent_path())
      folders.insert(folder);
  }
  // Deepest first: a folder's subfolders go before it.
  for (auto it = folders.rbegin(); it != folders.rend(); ++it) {
    std::error_code ec;
    if (fs::is_empty(out_dir / *it, ec) && !ec) fs::remove(out_dir / *it, ec);
  }
}

}  // namespace

std::string cached_head(const CachedOutputs& cached) {
  JsonObject options = cached.options;
  if (!cached.input_files.empty())
    options.push_back({"input_files", input_files_json(cached.input_files)});
  return cached.scene ? manifest_head(cached.command, options, *cached.scene)
                      : manifest_head(cached.command, options);
}

namespace {

/// What make_cached() knows of stale outputs before it makes them: their manifest's head and
/// the outputs the earlier manifest listed.
struct Stale {
  std::string head;
  std::vector<std::string> earlier;
};

/// Nothing when `cached`'s outputs are up to date (their dead temporaries removed), otherwise
/// what recording them needs, after telling `freshness.on_remake` why.
std::optional<Stale> stale_outputs(const CachedOutputs& cached, const Freshness& freshness) {
  std::string head = cached_head(cached);
  if (!freshness.force) {
    const std::optional<std::string> stale =
        output::manifest_stale(cached.manifest, head, cached.out_dir, freshness.verify);
    if (!stale) {
      // A run killed here (SIGKILL) left its temporaries beside the outputs this one keeps:
      // cleared as a run that writes would (docs/outputs.md, "Signals").
      output::remove_dead_temporaries(cached.manifest);
      for (const std::string& output : output::read_manifest(cached.manifest).outputs)
        output::remove_dead_temporaries(cached.out_dir / output);
      return std::nullopt;
    }
    std::error_code ec;
    if (freshness.on_remake && fs::exists(cached.manifest, ec))
      freshness.on_remake(cached.name, *stale);
  }
  return Stale{std::move(head), output::read_manifest(cached.manifest).outputs};
}

/// The manifest's note of outputs `made` from `cached`.
std::string made_note(const CachedOutputs& cached, const Made& made) {
  return (cached.scene ? manifest_note(*cached.scene) : std::string()) + made.note;
}

/// The outputs `made` recorded: the earlier run's others removed, then the manifest written
/// (removed where it cannot be, as it describes the outputs just replaced).
void record(const CachedOutputs& cached, const Stale& stale, const Made& made,
            const std::string& note) {
  std::vector<std::string> outputs;
  for (const auto& path : made.outputs)
    outputs.push_back(path.lexically_relative(cached.out_dir).generic_string());
  remove_outputs_of_earlier_run(cached.out_dir, stale.earlier, outputs);
  try {
    output::write_manifest(cached.manifest, stale.head, note, cached.out_dir, outputs);
  } catch (...) {
    std::error_code ec;
    fs::remove(cached.manifest, ec);
    throw;
  }
}

}  // namespace

Outcome make_cached(const CachedOutputs& cached, const Freshness& freshness,
                    const std::function<Made()>& make) {
  const std::optional<Stale> stale = stale_outputs(cached, freshness);
  if (!stale) return Outcome::up_to_date;
  Made made;
  std::string note;
  try {
    made = make();
    note = made_note(cached, made);
  } catch (const Interrupted&) {
    throw;  // nothing was put in place: the earlier outputs and their manifest stay
  } catch (...) {
    std::error_code ec;
    if (!cached.all_or_nothing) fs::remove(cached.manifest, ec);
    throw;
  }
  record(cached, *stale, made, note);
  return Outcome::made;
}

std::vector<Outcome> make_cached_together(const std::vector<CachedOutputs>& each,
                                          const Freshness& freshness,
                                          const std::function<Made(std::size_t)>& make,
                                          const std::function<void()>& put_in_place) {
  for (const CachedOutputs& cached : each)
    if (!cached.all_or_nothing)
      throw InternalError("make_cached_together: " + cached.name + " is not all or nothing");
  // A throw before everything is in place leaves every earlier output and manifest as it was
  // (each is all or nothing), so it goes on untouched.
  struct Step {
    std::size_t i;
    Stale stale;
    Made made;
    std::string note;
  };
  std::vector<Step> steps;
  for (std::size_t i = 0; i < each.size(); ++i) {
    std::optional<Stale> stale = stale_outputs(each[i], freshness);
    if (!stale) continue;
    Made made = make(i);
    std::string note = made_note(each[i], made);
    steps.push_back({i, std::move(*stale), std::move(made), std::move(note)});
  }
  put_in_place();
  // The manifests after every output, the last one's first.
  std::vector<Outcome> outcomes(each.size(), Outcome::up_to_date);
  for (auto step = steps.rbegin(); step != steps.rend(); ++step) {
    record(each[step->i], step->stale, step->made, step->note);
    outcomes[step->i] = Outcome::made;
  }
  return outcomes;
}

}  // namespace bookspin::cache
