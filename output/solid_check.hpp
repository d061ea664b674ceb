// Is a shell closed: every edge used exactly twice, once in each direction, and the faces around
// every vertex one fan? (The combinatorial half of a valid 2-manifold Solid; written parts must pass it, and
// the tests check the output files with it after deduplicating vertices by coordinates.)
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mc::output {

// A shell as surfaces of rings of vertex ids (rings not closed: last != first).
using Shell = std::vector<std::vector<std::vector<int64_t>>>;

// Empty when closed; otherwise a short description of the first defect found.
std::string closed_shell_defect(const Shell& shell);

}  // namespace mc::output
