#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

namespace {
ReadStageListener& listener() {
  static ReadStageListener instance;
  return instance;
}
}  // namespace

void set_read_stage_listener(ReadStageListener listener_function) { listener() = std::move(listener_function); }

void report_read_stage(const std::string& stage) {
  if (listener()) listener()(stage);
}

}  // namespace cadnurbs
