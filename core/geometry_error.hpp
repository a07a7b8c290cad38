#pragma once
// The one error type of the core model: which entity is wrong and why.
#include <stdexcept>
#include <string>

namespace cadnurbs {

// Thrown when geometry is invalid. what() is "<entity>: <reason>".
class GeometryError : public std::runtime_error {
 public:
  GeometryError(std::string entity, std::string reason)
      : std::runtime_error(entity + ": " + reason), entity_(std::move(entity)), reason_(std::move(reason)) {}
  const std::string& entity() const { return entity_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string entity_;
  std::string reason_;
};

}  // namespace cadnurbs
