#pragma once
// The files an Inline's or an EXTERNPROTO's url names, when they are local: a relative url (resolved in
// the directory of the file that names it) or a file: url, with %XX escapes decoded and a "#fragment"
// cut off. Remote urls (http:, urn: ... any scheme other than file:) are not followed: cadnurbs does not
// fetch from the network.
//   Each file is read once (text or gzip'd, classic or XML, as vrml_reader reads it) and its animation
//   taken at rest (animation_at_rest.hpp); the documents live as long as this object.
//   Following is bounded: a file that includes itself, directly or through others, is refused, and so is
//   a chain of more than kMaxLinkDepth files (the caller passes the chain it is in).
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

constexpr size_t kMaxLinkDepth = 8;

// The local file `url` names, if it is local and exists as a regular file; `directory`: that of the file
// naming it.
std::optional<std::filesystem::path> local_file_of_url(const std::string& url, const std::filesystem::path& directory);

class LinkedFiles {
 public:
  struct Opened {
    const NodeDocument* document = nullptr;  // null: not opened, `refusal` says why
    std::filesystem::path path;              // the file read (canonical)
    std::string url;                         // the url that named it, else the first url tried
    std::string refusal;                     // "not a local file", "it includes itself", a read error...
  };

  // The first of `urls` that names a local file, read. `chain`: canonical paths of the files being read
  // around this one (the outermost first), for the cycle and depth guards.
  Opened open(const std::vector<std::string>& urls, const std::filesystem::path& directory,
              const std::vector<std::filesystem::path>& chain);

 private:
  std::map<std::filesystem::path, std::unique_ptr<NodeDocument>> documents_;
};

}  // namespace cadnurbs
