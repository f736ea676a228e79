// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The aico module: Approximate Inference Control over a model and a TaskStack, with the
/// topological layer of the paper (Fig. 4). See docs/aico.md.
///
/// options.hpp (AicoMode, SweepMode, AicoOptions), problem.hpp (AicoProblem), workspace.hpp
/// (AicoWorkspace), result.hpp (AicoTermination, AicoSweepRecord, AicoResult), solver.hpp (the
/// stages of a sweep and solve()), topological.hpp (the topological layer, solve_topological()).
#pragma once

#include <topograsp/aico/options.hpp>
#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/result.hpp>
#include <topograsp/aico/solver.hpp>
#include <topograsp/aico/topological.hpp>
#include <topograsp/aico/workspace.hpp>
