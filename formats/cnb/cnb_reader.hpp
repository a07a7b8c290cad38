#pragma once
// Reads a .cnb file (docs/cnb.md) back into a scene.
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

// The scene from the file's bytes. Refuses damaged or truncated input with one FileError line,
// "<name>: byte N: <reason>" for the file's header and checksum, "<name>: decoded byte N: <reason>" for
// the payload behind them (N counted in the decoded payload), never allocating more than the remaining
// bytes can hold. Every decoded shape is validated (an invalid one is refused the same way).
Scene read_cnb(const std::string& bytes, const std::string& name);

}  // namespace cadnurbs
