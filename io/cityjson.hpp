// Umbrella header of the CityJSON part of io/.
#pragma once
#include "io/cityjson_building.hpp"
#include "io/cityjson_reader.hpp"
#include "io/cityjson_types.hpp"
#include "io/cityjson_writer.hpp"
#include "io/errors.hpp"
