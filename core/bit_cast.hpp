#pragma once
// std::bit_cast where the standard library has it. The browser module's (web/module) libc++, Emscripten
// 3.1.6's as Debian 12 ships it, has not: there, the same bits by memcpy. Libraries the module builds use
// this one.
#include <bit>
#include <cstring>
#include <type_traits>

namespace cadnurbs {

template <class To, class From>
To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>);
#if defined(__cpp_lib_bit_cast)
  return std::bit_cast<To>(from);
#else
  To to;
  std::memcpy(&to, &from, sizeof(To));
  return to;
#endif
}

}  // namespace cadnurbs
