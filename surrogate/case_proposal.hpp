#pragma once
// Where to simulate next: greedy maximum-variance design over a candidate grid. Step by
// step, the candidate with the largest latent predictive sd of ln eta_re (= relative sd
// of eta_re) is chosen and added to the training set as if simulated, with the library's
// median noise variance (the GP variance does not depend on the simulated value), so the
// next choice accounts for it. Hyper-parameters stay fixed.
#include <vector>

#include "surrogate/grid_refinement.hpp"
#include "surrogate/viscosity_surrogate.hpp"

namespace rbcal::surrogate {

struct ProposedCase : ParameterPoint {
  double eta_re = 0.0;       // current prediction there
  double relative_sd = 0.0;  // sd(ln eta_re) there before any of the proposed cases is added
  double relative_sd_when_chosen = 0.0;  // after the earlier proposals were added
  bool inside_hull = true;
};


// The k grid points (of all phi x Ca x lambda combinations of `candidates`) with the
// largest variance, in the order chosen. Fewer if the grid has fewer points. Candidates
// equal to a point of `simulated` (to 1e-9 relative) are skipped: the surrogate trains on
// the actual phi of each case, so a planned phi keeps some variance even where it was
// simulated, and would otherwise be proposed again.
std::vector<ProposedCase> propose_cases(const ViscositySurrogate& surrogate, const ParameterGrid& candidates,
                                        std::size_t k, const std::vector<ParameterPoint>& simulated = {});

}  // namespace rbcal::surrogate
