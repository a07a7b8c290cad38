#include "converters/batch/library_listing.hpp"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include "converters/content_format.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace fs = std::filesystem;

namespace {

// Whether `path` (made canonical) lies inside the canonical folder `root`.
bool inside(const fs::path& path, const fs::path& root) {
  const auto mismatch = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return mismatch.first == root.end();
}

}  // namespace

std::vector<LibraryPart> list_library(const fs::path& in_dir) {
  std::error_code error;
  const fs::path root = fs::canonical(in_dir, error);
  if (error || !fs::is_directory(root)) throw FileError(in_dir.string() + ": not a folder that can be read");
  std::vector<LibraryPart> parts;
  fs::recursive_directory_iterator walk(root, fs::directory_options::none, error);
  if (error) throw FileError(in_dir.string() + ": cannot be walked (" + error.message() + ")");
  for (const fs::recursive_directory_iterator end; walk != end; walk.increment(error)) {
    if (error) throw FileError(in_dir.string() + ": cannot be walked (" + error.message() + ")");
    const fs::directory_entry& entry = *walk;
    if (!entry.is_regular_file(error)) continue;  // folders are walked; devices, FIFOs, links to folders are not parts
    LibraryPart part;
    part.relative = entry.path().lexically_relative(root).generic_string();  // not through links
    const fs::path target = fs::canonical(entry.path(), error);
    if (error || !inside(target, root)) {
      part.refusal = "links to " + (error ? std::string("nothing readable") : target.string()) + ", outside the library";
      parts.push_back(std::move(part));
      continue;
    }
    // The name first: it is what the vendor declared, and a file that does not hold what its name says
    // should fail as that format rather than pass as another. Content for the names that say nothing.
    const FileFormat* named = format_of(entry.path().string());
    try {
      part.format = named && named->read ? named : format_by_content(entry.path().string());
    } catch (const FileError&) {
      continue;  // an unnamed file that cannot even be looked at is no part we know of
    }
    if (!part.format) continue;  // neither name nor content is a part's (READMEs, licences)
    part.by_content = part.format != named;
    parts.push_back(std::move(part));
  }
  std::sort(parts.begin(), parts.end(), [](const LibraryPart& a, const LibraryPart& b) { return a.relative < b.relative; });
  return parts;
}

std::vector<LibraryPart> of_formats(const std::vector<LibraryPart>& parts, const std::vector<const FileFormat*>& formats) {
  if (formats.empty()) return parts;
  std::vector<LibraryPart> kept;
  for (const auto& part : parts) {
    const FileFormat* format = part.format ? part.format : format_of(part.relative);
    if (std::find(formats.begin(), formats.end(), format) != formats.end()) kept.push_back(part);
  }
  return kept;
}

std::vector<LibraryPart> shard_of(const std::vector<LibraryPart>& parts, int shard, int shards) {
  if (shards < 1 || shard < 0 || shard >= shards) throw std::invalid_argument("shard_of: needs 0 <= shard < shards");
  std::vector<LibraryPart> slice;
  for (size_t i = static_cast<size_t>(shard); i < parts.size(); i += static_cast<size_t>(shards)) slice.push_back(parts[i]);
  return slice;
}

fs::path output_stem(const fs::path& out_dir, const std::string& relative) {
  const fs::path name(relative);
  if (name.is_absolute()) throw std::invalid_argument("its name is an absolute path");
  for (const auto& component : name)
    if (component == "..") throw std::invalid_argument("its name climbs out of the folder ('..')");
  const fs::path root = fs::weakly_canonical(out_dir);
  const fs::path destination = fs::weakly_canonical(root / name);
  if (!inside(destination, root)) throw std::invalid_argument("its output would land outside OUT_DIR, at " + destination.string());
  return destination;
}

}  // namespace cadnurbs
