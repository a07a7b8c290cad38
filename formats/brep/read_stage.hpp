#pragma once
// Where a B-rep read (read_step, read_iges) is: "parse" (OCCT reads the file), "transfer" (OCCT builds
// shapes), "face N" (face N of the scene, counted from 1, becomes a trimmed NURBS). A listener, when set,
// hears each stage as it starts; converters/walled_read passes them to the parent process so that a crash
// or a limit can be said with the stage it happened in. No process code here; no OCCT types.
#include <functional>
#include <string>

namespace cadnurbs {

using ReadStageListener = std::function<void(const std::string& stage)>;

// Replaces the process-wide listener (an empty function: none). Not thread-safe: set it before reading.
void set_read_stage_listener(ReadStageListener listener);

// Tells the listener, if any, that `stage` starts.
void report_read_stage(const std::string& stage);

}  // namespace cadnurbs
