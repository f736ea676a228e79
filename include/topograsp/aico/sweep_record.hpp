// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AicoSweepRecord: what one AICO sweep did.
#pragma once

namespace topograsp {

/// What one AICO sweep did, for logs and plots.
struct AicoSweepRecord {
  double cost = 0.0;      ///< true cost of the sweep's trajectory (before acceptance)
  double damping = 0.0;   ///< damping alpha the sweep ran with
  double seconds = 0.0;   ///< wall time of the sweep including the cost evaluation (s)
  double step = 0.0;      ///< largest change of a configuration against the accepted one (rad)
  int relocations = 0;    ///< task re-evaluations during the sweep
  bool accepted = false;  ///< whether the trajectory was kept
};

}  // namespace topograsp
