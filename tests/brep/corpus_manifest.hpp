#pragma once
// The shared corpus's list of files (../shared/corpus/MANIFEST.tsv, path column).
#include <string>
#include <vector>

namespace cadnurbs::test {

// Paths relative to the corpus folder of the MANIFEST.tsv rows whose path starts with one of `prefixes`
// (e.g. "step/", "iges/"), in file order. Empty when the manifest cannot be read.
std::vector<std::string> corpus_paths(const std::vector<std::string>& prefixes);

// A corpus path as a test name (letters and digits kept, the rest '_').
std::string corpus_test_name(const std::string& relative);

// Absolute path of a corpus file.
std::string corpus_file(const std::string& relative);

}  // namespace cadnurbs::test
