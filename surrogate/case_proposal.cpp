#include "surrogate/case_proposal.hpp"

#include <algorithm>
#include <cmath>

namespace rbcal::surrogate {

std::vector<ProposedCase> propose_cases(const ViscositySurrogate& surrogate, const ParameterGrid& candidates,
                                        std::size_t k, const std::vector<ParameterPoint>& simulated) {
  auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); };
  auto already_simulated = [&](double phi, double ca, double lambda) {
    for (const ParameterPoint& s : simulated)
      if (same(s.phi, phi) && same(s.capillary_number, ca) && same(s.viscosity_ratio, lambda)) return true;
    return false;
  };
  std::vector<ProposedCase> pool;
  for (double phi : candidates.phi)
    for (double ca : candidates.capillary_number)
      for (double lambda : candidates.viscosity_ratio) {
        if (already_simulated(phi, ca, lambda)) continue;
        ProposedCase p{{phi, ca, lambda}};
        p.eta_re = surrogate.predict(phi, ca, lambda).eta_re;
        p.relative_sd = surrogate.log_viscosity_sd(phi, ca, lambda);
        p.inside_hull = surrogate.inside_hull(phi, ca, lambda);
        pool.push_back(p);
      }

  std::vector<TrainingCase> augmented = surrogate.training_cases();
  std::vector<double> noise;
  for (const TrainingCase& c : augmented) noise.push_back(c.noise_variance);
  std::sort(noise.begin(), noise.end());
  const double typical_noise = noise[noise.size() / 2];

  std::vector<ProposedCase> chosen;
  std::vector<bool> taken(pool.size(), false);
  const GaussianProcessHyperparameters& hp = surrogate.process().hyperparameters();
  while (chosen.size() < k && chosen.size() < pool.size()) {
    const ViscositySurrogate current = chosen.empty() ? surrogate : ViscositySurrogate(augmented, hp);
    std::size_t best = pool.size();
    double best_sd = -1.0;
    for (std::size_t i = 0; i < pool.size(); ++i) {
      if (taken[i]) continue;
      const double sd = current.log_viscosity_sd(pool[i].phi, pool[i].capillary_number, pool[i].viscosity_ratio);
      if (sd > best_sd) best_sd = sd, best = i;  // strict '>': ties go to the first in grid order
    }
    taken[best] = true;
    ProposedCase p = pool[best];
    p.relative_sd_when_chosen = best_sd;
    chosen.push_back(p);
    augmented.push_back({"proposed", p.phi, std::log(p.capillary_number), std::log(p.viscosity_ratio), std::log(p.eta_re),
                         typical_noise});
  }
  return chosen;
}

}  // namespace rbcal::surrogate
