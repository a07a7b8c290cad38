#pragma once
// Where a B-rep read (read_step, read_iges) is: "parse" (OCCT reads the file), "transfer" (OCCT builds
// shapes), "face N" (face N of the scene, counted from 1, becomes a trimmed NURBS). The caller passes a
// listener to the reader, which tells it each stage as it starts; converters/walled_read passes them to
// the parent process so that a crash or a limit can be said with the stage it happened in. No process
// code here; no OCCT types.
#include <functional>
#include <string>

namespace cadnurbs {

using ReadStageListener = std::function<void(const std::string& stage)>;

// Tells `listener`, when there is one, that `stage` starts.
inline void tell_stage(const ReadStageListener& listener, const std::string& stage) {
  if (listener) listener(stage);
}

}  // namespace cadnurbs
