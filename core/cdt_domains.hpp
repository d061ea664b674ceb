// Nesting depth of every face of a 2D constrained triangulation of polygon rings (CGAL's polygon
// triangulation example): 0 outside, +1 across each constraint, so odd depths are inside the
// polygon and holes are excluded. One implementation for every face triangulation (core/soup.cpp,
// core/solid_validation.cpp); `nesting(face)` gives the int slot of a face handle.
#pragma once
#include <list>

namespace mc {

template <class CDT, class Nesting>
void mark_nesting(CDT& cdt, Nesting nesting) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) nesting(f) = -1;
  std::list<typename CDT::Edge> border;
  auto flood = [&](typename CDT::Face_handle start, int level) {
    if (nesting(start) != -1) return;
    std::list<typename CDT::Face_handle> queue{start};
    while (!queue.empty()) {
      typename CDT::Face_handle f = queue.front();
      queue.pop_front();
      if (nesting(f) != -1) continue;
      nesting(f) = level;
      for (int i = 0; i < 3; ++i) {
        typename CDT::Face_handle n = f->neighbor(i);
        if (nesting(n) != -1) continue;
        if (cdt.is_constrained(typename CDT::Edge(f, i))) border.push_back(typename CDT::Edge(f, i));
        else queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const typename CDT::Edge e = border.front();
    border.pop_front();
    typename CDT::Face_handle n = e.first->neighbor(e.second);
    if (nesting(n) == -1) flood(n, nesting(e.first) + 1);
  }
}

}  // namespace mc
