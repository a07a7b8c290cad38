#include "corpus_manifest.hpp"

#include <cctype>
#include <fstream>

namespace cadnurbs::test {

std::string corpus_file(const std::string& relative) { return std::string(CADNURBS_SHARED_DIR) + "/corpus/" + relative; }

std::string corpus_test_name(const std::string& relative) {
  std::string name;
  for (char c : relative) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

std::vector<std::string> corpus_paths(const std::vector<std::string>& prefixes) {
  std::vector<std::string> out;
  std::ifstream in(corpus_file("MANIFEST.tsv"));
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (header) {
      header = false;
      continue;
    }
    const std::string path = line.substr(0, line.find('\t'));
    for (const auto& prefix : prefixes)
      if (path.rfind(prefix, 0) == 0) out.push_back(path);
  }
  return out;
}

}  // namespace cadnurbs::test
