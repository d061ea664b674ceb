// libFuzzer target: the .city.json reader (two streaming passes), building extraction, writer.
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mc::fuzz::read_extract_write(mc::fuzz::write_input(data, size, ".city.json"), ".city.json");
  return 0;
}
