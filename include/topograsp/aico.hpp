// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The aico module: Approximate Inference Control over a model and a TaskStack, with the
/// topological layer of the paper (Fig. 4). See docs/aico.md.
#pragma once

#include <topograsp/aico/aico_mode.hpp>
#include <topograsp/aico/options.hpp>
#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/result.hpp>
#include <topograsp/aico/solver.hpp>
#include <topograsp/aico/sweep_mode.hpp>
#include <topograsp/aico/sweep_record.hpp>
#include <topograsp/aico/termination.hpp>
#include <topograsp/aico/topological_layer.hpp>
#include <topograsp/aico/topological_result.hpp>
#include <topograsp/aico/topological_stack.hpp>
#include <topograsp/aico/topology_mode.hpp>
#include <topograsp/aico/topology_options.hpp>
#include <topograsp/aico/workspace.hpp>
