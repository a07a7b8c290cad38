#pragma once
// The parts of a library folder, in a stable order, and where each one's outputs go: the first step of
// `cadnurbs batch`.
#include <filesystem>
#include <string>
#include <vector>

#include "converters/file_formats.hpp"

namespace cadnurbs {

struct LibraryPart {
  std::string relative;                  // path under IN_DIR, '/'-separated: the part's name everywhere
  const FileFormat* format = nullptr;    // how it is read; null when refused
  bool by_content = false;               // the name says no input format; the content told it
  std::string refusal;                   // why it is not read ("" when it is)
};

// Takes the library folder. Returns every regular file under it (links to files included, folders
// walked but links to folders not followed) whose name or, when the name says nothing, content shows an
// input format (content_format.hpp), sorted by `relative` bytewise. A file named as an input format is
// read as that format even when its content is another (it then fails, saying why). Files that are
// neither (READMEs, licences) are left out. A part is listed with a refusal when it is a link that leads out of
// the folder. Throws FileError "<in_dir>: ..." when the folder cannot be walked.
std::vector<LibraryPart> list_library(const std::filesystem::path& in_dir);

// The parts read as one of `formats` (a refused part: as its name says), in the same order; all of them
// when `formats` is empty. `batch --inputs step,iges` keeps a library's shipped meshes out of a run.
std::vector<LibraryPart> of_formats(const std::vector<LibraryPart>& parts, const std::vector<const FileFormat*>& formats);

// The parts of slice `shard` of `shards` (0 <= shard < shards): every shards-th part of the stable order,
// starting at `shard`, so that the slices are disjoint, cover the library and are about equally long.
std::vector<LibraryPart> shard_of(const std::vector<LibraryPart>& parts, int shard, int shards);

// Where the outputs of the part `relative` go: OUT_DIR/<relative> (an extension is appended per output).
// Refuses (std::invalid_argument, a reason for the part's record) a relative path that is absolute or has
// a ".." component, and a destination that, once existing links in OUT_DIR are followed, lies outside
// OUT_DIR.
std::filesystem::path output_stem(const std::filesystem::path& out_dir, const std::string& relative);

}  // namespace cadnurbs
