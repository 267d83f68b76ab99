// The measurement layer of the virtual slump test and vane rheometer (all of paddy::measure).
// Definitions, sources, parameters and known biases: docs/measurement.md.
#pragma once

#include <paddy/measure/circle_fit.hpp>
#include <paddy/measure/clusters.hpp>
#include <paddy/measure/coarse_graining.hpp>
#include <paddy/measure/common.hpp>
#include <paddy/measure/herschel_bulkley.hpp>
#include <paddy/measure/relative_error.hpp>
#include <paddy/measure/slump.hpp>
#include <paddy/measure/slump_flow.hpp>
#include <paddy/measure/surface_stress.hpp>
#include <paddy/measure/top_view.hpp>
#include <paddy/measure/vane.hpp>
