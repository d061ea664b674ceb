// Roles of a level's masses (docs/massing.md, "Roles"): ordered rules over the masses
// (massing/masses.hpp), the first that applies wins; every part takes its mass's role.
#pragma once
#include "core/params.hpp"
#include "massing/massing.hpp"

namespace mc::massing {

void assign_roles(LevelMassing& L, const MassingParams& p);

}  // namespace mc::massing
