#pragma once
// Atomic output for writers that can only write by path (OCCT's): write a temporary beside the target,
// then rename it over the target. No OCCT types.
#include <functional>
#include <string>

namespace cadnurbs {

// Calls write(temporary) with temporary = "<path>.tmp<process id>", then renames the temporary to `path`,
// so an interrupted or failed run never leaves a partial `path`. Whatever write throws is passed on after
// the temporary is removed; a failed rename throws FileError "<path>: cannot write (<reason>)".
void write_through_temporary(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace cadnurbs
