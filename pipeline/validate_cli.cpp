// PLACEHOLDER: replaced by the real implementation (work in progress).
#include <cstdio>
#include "pipeline/subcommands.hpp"
namespace mc::pipeline {
int validate_main(int, char**) {
  std::fprintf(stderr, "morphcut-city: validate is not implemented yet\n");
  return 2;
}
}  // namespace mc::pipeline
