#pragma once
// The seed papers' own figures, printed in every report as a reference table labelled as theirs, so
// that a reader can set our measured numbers beside them.
#include <string>
#include <vector>

namespace cadnurbs {

struct ReferenceFigure {
  std::string source;    // "seed 001, §6.1"
  std::string part;      // "90° handrail capping"
  std::string quantity;  // "NURBS floats"
  std::string value;     // as the paper gives it: "2,468"
};

const std::vector<ReferenceFigure>& reference_figures();

}  // namespace cadnurbs
