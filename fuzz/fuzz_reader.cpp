// A libFuzzer target for one reader: GENMESH_FUZZ_FORMAT is
// genmesh::File_format::off, obj, ply or stl (fuzz/CMakeLists.txt builds one
// executable per format). See genmesh_fuzz.h.
#include "genmesh_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  genmesh_fuzz::read_one(GENMESH_FUZZ_FORMAT, data, size);
  return 0;
}
