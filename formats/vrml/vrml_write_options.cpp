#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs {

VrmlDialect dialect_of(VrmlEncoding encoding) {
  return encoding == VrmlEncoding::vrml97 ? VrmlDialect::vrml97 : VrmlDialect::x3d;
}

}  // namespace cadnurbs
