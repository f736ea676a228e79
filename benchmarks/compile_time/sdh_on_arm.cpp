// SPDX-License-Identifier: BSD-3-Clause
// Compile-time benchmark (benchmarks/compile_time.sh): the README tour's transfer snippet, the
// paper's planner: a human grasp of the hammer transferred to the SDH on the Schunk arm by
// transfer_topological (AICO over the 14 joints).
#include <cstdio>

#include <topograsp/grasp/transfer.hpp>

int main() {
  using namespace topograsp;
  const GraspObject hammer = objects::hammer();
  const auto hypotheses = box_hypotheses(hammer);
  const HumanGrasp demo = demonstrate(hammer, hypotheses[26], 26);
  const SdhTransfer sdh = transfer_topological(hammer, demo);
  std::printf("%s after %d sweeps\n", sdh.stable() ? "stable" : "unstable", sdh.sweeps);
}
