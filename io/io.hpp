// io.hpp — everything of flipflop::io: point files in and out, canonical
// index output out and back in (for the certifier).
#pragma once

#include "io/index_io.hpp"
#include "io/input_error.hpp"
#include "io/read_points.hpp"
#include "io/write_points.hpp"
