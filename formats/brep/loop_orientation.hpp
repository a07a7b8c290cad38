#pragma once
// orient_loops moved to core (it needs no OCCT); this header stays so existing includes compile.
#include "core/loop_orientation.hpp"
