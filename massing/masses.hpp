// Parts grouped into masses as a person sees them (docs/massing.md, "Masses"), before roles:
//   1. a part narrower in plan than thin_width (a façade layer, a wall skin) is a layer of the mass
//      of the neighbour it shares most with;
//   2. a raised part with few walls of its own (a gable wedge, a hip piece, a valley piece, a roof
//      slab) resting on a part is a roof piece of that part's mass, whatever the contact below;
//   3. the other parts (bodies) are one mass where they are pieces of one uniform volume: tops and
//      bottoms within mass_height_tolerance, a shared vertical face of at least
//      mass_shared_fraction x the smaller height x the smaller width, and together about as convex
//      as one part (mass_convexity).
// Every mass gets its geometry (z range, volume, hull, footprint union, width and length) and its
// contacts with the other masses.
#pragma once
#include <vector>

#include "core/params.hpp"
#include "core/polygon_mesh.hpp"
#include "massing/massing.hpp"

namespace mc::massing {

// Fills L.masses and each part's `mass` and `piece` (parts must have their geometry and contacts;
// `ground` is the building's lowest z at this level).
void group_masses(LevelMassing& L, const std::vector<PolygonMesh>& meshes, double ground,
                  const MassingParams& p);

}  // namespace mc::massing
