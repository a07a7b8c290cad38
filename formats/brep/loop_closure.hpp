#pragma once
// join_segments moved to core (it needs no OCCT); this header stays so existing includes compile.
#include "core/loop_closure.hpp"
