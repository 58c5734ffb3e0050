// read_indices_check.cpp — fuzz_read_indices: any bytes as index output.
//
// Byte 0, bit 0 chooses the reader: set → io::read_triangles ("i j k" per
// line, or Qhull's "i Qt" output), clear → io::read_index_cycle (one index
// per line); the remaining bytes are the file. The reader must either
//   * return indices that survive the round trip: written back with
//     io::write_triangles / io::write_hull2 and read again, the same list; or
//   * throw io::InputError whose message is one line naming the file.
// Any other exception, a crash, a hang or a sanitizer report is a bug.
#include <exception>
#include <sstream>
#include <string>
#include <type_traits>

#include "fuzz/checks.hpp"
#include "fuzz/fuzz_input.hpp"
#include "fuzz/input_error_check.hpp"
#include "fuzz/temp_file.hpp"
#include "io/io.hpp"

namespace flipflop::fuzz {

namespace {

const char* kTarget = "fuzz_read_indices";

template <class List>
List read_list(const std::string& path) {
  if constexpr (std::is_same_v<List, std::vector<Triangle>>)
    return io::read_triangles(path);
  else
    return io::read_index_cycle(path);
}
void write_list(std::ostream& os, const std::vector<Triangle>& t) { io::write_triangles(os, t); }
void write_list(std::ostream& os, const std::vector<Index>& c) { io::write_hull2(os, c); }

template <class List>
void check(const TempFile& file) {
  List list;
  try {
    list = read_list<List>(file.path());
  } catch (const io::InputError& e) {
    check_input_error(kTarget, e, file.path());
    return;
  } catch (const std::exception& e) {
    fail(kTarget, std::string("exception other than io::InputError: ") + e.what());
  } catch (...) {
    fail(kTarget, "non-standard exception");
  }
  std::ostringstream os;
  write_list(os, list);
  const std::string text = os.str();
  TempFile back("indices-roundtrip", ".txt", reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  List again;
  try {
    again = read_list<List>(back.path());
  } catch (const std::exception& e) {
    fail(kTarget, std::string("written indices do not read back: ") + e.what(), describe(list));
  }
  if (again != list) fail(kTarget, "write + read changed the indices", describe(list) + "\n" + describe(again));
}

}  // namespace

bool check_read_indices_input(const std::uint8_t* data, std::size_t size) {
  const bool triangles = size > 0 && (data[0] & 1);
  TempFile file("indices", ".txt", size > 0 ? data + 1 : data, size > 0 ? size - 1 : 0);
  if (triangles)
    check<std::vector<Triangle>>(file);
  else
    check<std::vector<Index>>(file);
  return true;
}

}  // namespace flipflop::fuzz
