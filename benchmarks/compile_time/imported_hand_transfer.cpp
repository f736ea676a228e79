// SPDX-License-Identifier: BSD-3-Clause
// Compile-time benchmark (benchmarks/compile_time.sh): the translation unit a user writes for a
// hand imported from its model file with a hand description (the Allegro: a generated header plus
// its description, as models/allegro_hand.hpp is): human demonstrations on the hammer and the
// bottle, each stable one transferred to the hand by every method of transfer_hand.
#include <cstdio>

#include <topograsp/grasp/transfer/hand.hpp>
#include <topograsp/model/models/allegro_hand.hpp>

int main() {
  using namespace topograsp;
  for (const GraspObject& object : {objects::hammer(), objects::bottle()}) {
    const auto hypotheses = box_hypotheses(object);
    for (std::size_t i = 0; i < hypotheses.size(); ++i) {
      const HumanGrasp demo = demonstrate(object, hypotheses[i], static_cast<int>(i));
      if (!demo.stable()) continue;
      for (const TransferMethod m : {TransferMethod::topological, TransferMethod::transplant,
                                     TransferMethod::fingertip, TransferMethod::virtual_finger}) {
        const auto r = transfer_hand<models::allegro_hand>(m, object, source_grasp(demo));
        std::printf("%s %zu %s: %s\n", object.name.c_str(), i, to_string(m).data(),
                    r.stable() ? "stable" : r.reason.c_str());
      }
    }
  }
}
