// Parts grouped into masses as a person sees them (docs/massing.md, "Masses"), before roles:
//   1. pieces: a part narrower in plan than thin_width (a façade layer, a wall skin), or a
//      façade zone under twice that lining a larger part from its base, is a layer; a raised wedge or
//      slab with few walls of its own, or covering roof_min_cover of what it rests on, is a roof
//      piece (whatever the contact below); every other part is a body;
//   2. bodies sharing a vertical face of at least mass_shared_fraction x the smaller height x the
//      smaller width, with tops within mass_height_tolerance (or mass_height_share of the height),
//      are one mass when one stands on something lower (bottoms apart: flush with the other's
//      top), or, bottoms within the tolerance too, when they have one flat roof or are together
//      about as convex as one part (mass_convexity); with tops apart and bottoms together, when
//      the lower is a slice of the higher cut off under its slope (slice_*);
//   3. roof pieces join the mass they rest on; 4. layers the mass they lean on;
//   5. step 2 again on the masses, across their layers;
//   6. a mass covered (storey_min_cover) by one mass standing on it is that mass's lower storey.
// Every mass gets its geometry (z range, volume, hull, footprint union, width and length) and its
// contacts with the other masses.
#pragma once
#include <vector>

#include "core/params.hpp"
#include "core/polygon_mesh.hpp"
#include "massing/massing.hpp"

namespace mc::massing {

// Fills L.masses and each part's `mass` and `piece` (parts must have their geometry, contacts and
// `grounded`; a mass is grounded when one of its parts is).
void group_masses(LevelMassing& L, const std::vector<PolygonMesh>& meshes, const MassingParams& p);

}  // namespace mc::massing
