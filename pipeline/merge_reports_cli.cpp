// PLACEHOLDER: replaced by the real implementation (work in progress).
#include <cstdio>
#include "pipeline/subcommands.hpp"
namespace mc::pipeline {
int merge_reports_main(int, char**) {
  std::fprintf(stderr, "morphcut-city: merge_reports is not implemented yet\n");
  return 2;
}
}  // namespace mc::pipeline
