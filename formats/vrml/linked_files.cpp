#include "formats/vrml/linked_files.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "formats/common/file_io.hpp"
#include "formats/vrml/animation_at_rest.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {

namespace {

std::string percent_decoded(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

}  // namespace

std::optional<std::filesystem::path> local_file_of_url(const std::string& url, const std::filesystem::path& directory) {
  std::string path = url.substr(0, url.find('#'));
  if (path.starts_with("file://")) {
    path = path.substr(7);
    if (path.starts_with("localhost/")) path = path.substr(9);
    if (!path.starts_with("/")) return std::nullopt;  // file://host/...: another machine
  } else if (path.starts_with("file:")) {
    path = path.substr(5);
  } else {
    // A scheme ("http:", "urn:") comes before any '/'.
    const size_t colon = path.find(':');
    if (colon != std::string::npos && colon < path.find('/')) return std::nullopt;
  }
  if (path.empty()) return std::nullopt;
  std::filesystem::path file(percent_decoded(path));
  if (file.is_relative()) file = directory / file;
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return std::nullopt;
  return std::filesystem::weakly_canonical(file, error);
}

LinkedFiles::Opened LinkedFiles::open(const std::vector<std::string>& urls, const std::filesystem::path& directory,
                                      const std::vector<std::filesystem::path>& chain) {
  Opened out;
  out.url = urls.empty() ? std::string() : urls.front();
  out.refusal = "not a local file";
  for (const auto& url : urls) {
    auto file = local_file_of_url(url, directory);
    if (!file) continue;
    out.url = url;
    out.path = *file;
    if (std::find(chain.begin(), chain.end(), *file) != chain.end()) {
      out.refusal = "it includes itself";
      return out;
    }
    if (chain.size() >= kMaxLinkDepth) {
      out.refusal = "files included more than " + std::to_string(kMaxLinkDepth) + " deep";
      return out;
    }
    auto& document = documents_[*file];
    if (!document) {
      try {
        auto read = std::make_unique<NodeDocument>(parse_vrml_document(read_file(file->string()), file->string()));
        apply_animation_at_rest(*read);
        document = std::move(read);
      } catch (const FileError& e) {
        documents_.erase(*file);
        out.refusal = e.what();
        return out;
      }
    }
    out.document = document.get();
    out.refusal.clear();
    return out;
  }
  return out;
}

}  // namespace cadnurbs
