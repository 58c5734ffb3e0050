// decimal.hpp — shortest round-trip decimal output (internal to io/).
#pragma once

#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>

namespace flipflop::io::detail {

// Appends v as the shortest decimal that std::from_chars reads back exactly.
template <class T>
void put_decimal(std::string& out, T v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// Writes `out` once it has grown (or always, with force): flat memory on
// large outputs.
inline void drain(std::ostream& os, std::string& out, bool force) {
  if (force || out.size() >= (std::size_t{1} << 16)) {
    os.write(out.data(), static_cast<std::streamsize>(out.size()));
    out.clear();
  }
}

}  // namespace flipflop::io::detail
