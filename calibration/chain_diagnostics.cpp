#include "calibration/chain_diagnostics.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "calibration/quantiles.hpp"

namespace rbcal::calibration {

namespace {

// A NaN has no rank: sorting it is undefined, and grouping ties around it never ends.
void check_finite(const ChainSet& chains) {
  for (std::size_t j = 0; j < chains.size(); ++j)
    for (std::size_t i = 0; i < chains[j].size(); ++i)
      if (!std::isfinite(chains[j][i]))
        throw std::invalid_argument("chain diagnostics: draw " + std::to_string(i) + " of chain " + std::to_string(j) +
                                    " is not finite (" + std::to_string(chains[j][i]) + ")");
}

void check(const ChainSet& chains) {
  if (chains.empty() || chains.front().size() < 4)
    throw std::invalid_argument("chain diagnostics need at least one chain of at least 4 draws");
  for (const auto& c : chains)
    if (c.size() != chains.front().size()) throw std::invalid_argument("chain diagnostics need chains of equal length");
  check_finite(chains);
}

double mean_of(const std::vector<double>& x) { return std::accumulate(x.begin(), x.end(), 0.0) / x.size(); }

struct VarianceComponents {
  double within = 0.0;    // W: mean of the chains' variances (denominator n - 1)
  double var_plus = 0.0;  // (n-1)/n W + B/n
};

VarianceComponents variance_components(const ChainSet& chains) {
  const double n = static_cast<double>(chains.front().size());
  const double m = static_cast<double>(chains.size());
  std::vector<double> means;
  double within = 0.0;
  for (const auto& c : chains) {
    const double mu = mean_of(c);
    means.push_back(mu);
    double ss = 0.0;
    for (double x : c) ss += (x - mu) * (x - mu);
    within += ss / (n - 1.0);
  }
  within /= m;
  double between_over_n = 0.0;  // B / n = variance of the chain means
  if (chains.size() > 1) {
    const double grand = mean_of(means);
    for (double mu : means) between_over_n += (mu - grand) * (mu - grand);
    between_over_n /= (m - 1.0);
  }
  return {within, (n - 1.0) / n * within + between_over_n};
}

double rhat_of_split(const ChainSet& split) {
  const VarianceComponents v = variance_components(split);
  if (v.within <= 0.0) return v.var_plus <= 0.0 ? 1.0 : std::numeric_limits<double>::infinity();
  return std::sqrt(v.var_plus / v.within);
}

double ess_of_split(const ChainSet& split) {
  const std::size_t n = split.front().size();
  const double m = static_cast<double>(split.size());
  const VarianceComponents v = variance_components(split);
  if (!(v.var_plus > 0.0)) return m * static_cast<double>(n);  // constant draws: no autocorrelation to speak of
  std::vector<double> means;
  for (const auto& c : split) means.push_back(mean_of(c));
  // Mean over chains of the autocovariance at lag t (denominator n, as in Stan / Geyer).
  auto mean_autocovariance = [&](std::size_t t) {
    double sum = 0.0;
    for (std::size_t j = 0; j < split.size(); ++j) {
      const auto& c = split[j];
      double s = 0.0;
      for (std::size_t i = 0; i + t < n; ++i) s += (c[i] - means[j]) * (c[i + t] - means[j]);
      sum += s / static_cast<double>(n);
    }
    return sum / m;
  };
  const double w_biased = mean_autocovariance(0);  // = (n-1)/n W
  const double within = w_biased * static_cast<double>(n) / (static_cast<double>(n) - 1.0);
  auto rho = [&](std::size_t t) { return 1.0 - (within - mean_autocovariance(t)) / v.var_plus; };
  // Geyer's initial monotone sequence on pair sums P_k = rho_2k + rho_2k+1 (rho_0 = 1).
  double sum_pairs = 0.0;
  double previous_pair = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t + 1 < n; t += 2) {
    double pair = (t == 0 ? 1.0 : rho(t)) + rho(t + 1);
    if (pair < 0.0) break;
    pair = std::min(pair, previous_pair);
    sum_pairs += pair;
    previous_pair = pair;
  }
  const double tau = std::max(-1.0 + 2.0 * sum_pairs, 1.0 / std::log10(m * static_cast<double>(n)));
  return m * static_cast<double>(n) / tau;
}

ChainSet folded(const ChainSet& chains) {
  std::vector<double> all;
  for (const auto& c : chains) all.insert(all.end(), c.begin(), c.end());
  const double median = quantile(all, 0.5);
  ChainSet result = chains;
  for (auto& c : result)
    for (double& x : c) x = std::abs(x - median);
  return result;
}

ChainSet indicator(const ChainSet& chains, double threshold) {
  ChainSet result = chains;
  for (auto& c : result)
    for (double& x : c) x = x <= threshold ? 1.0 : 0.0;
  return result;
}

}  // namespace

ChainSet split_chains(const ChainSet& chains) {
  check(chains);
  const std::size_t half = chains.front().size() / 2;
  const std::size_t second = chains.front().size() - half;  // odd length: skip the middle draw
  ChainSet split;
  for (const auto& c : chains) {
    split.emplace_back(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(half));
    split.emplace_back(c.begin() + static_cast<std::ptrdiff_t>(second), c.end());
  }
  return split;
}

ChainSet rank_normalize(const ChainSet& chains) {
  check_finite(chains);
  for (const auto& c : chains)
    if (c.size() != chains.front().size()) throw std::invalid_argument("chain diagnostics need chains of equal length");
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t j = 0; j < chains.size(); ++j)
    for (std::size_t i = 0; i < chains[j].size(); ++i) order.push_back({chains[j][i], j * chains[0].size() + i});
  std::sort(order.begin(), order.end());
  const double s = static_cast<double>(order.size());
  const boost::math::normal standard_normal;
  ChainSet result = chains;
  for (std::size_t k = 0; k < order.size();) {
    std::size_t end = k;
    while (end < order.size() && order[end].first == order[k].first) ++end;
    const double rank = 0.5 * static_cast<double>(k + 1 + end);  // average of ranks k+1 .. end
    const double z = boost::math::quantile(standard_normal, (rank - 0.375) / (s + 0.25));
    for (std::size_t q = k; q < end; ++q) {
      const std::size_t flat = order[q].second;
      result[flat / chains[0].size()][flat % chains[0].size()] = z;
    }
    k = end;
  }
  return result;
}

double split_rhat(const ChainSet& chains) { return rhat_of_split(split_chains(chains)); }

double rank_normalized_split_rhat(const ChainSet& chains) {
  const ChainSet split = split_chains(chains);
  return std::max(rhat_of_split(rank_normalize(split)), rhat_of_split(rank_normalize(folded(split))));
}

double effective_sample_size(const ChainSet& chains) { return ess_of_split(split_chains(chains)); }

double bulk_effective_sample_size(const ChainSet& chains) { return ess_of_split(rank_normalize(split_chains(chains))); }

double tail_effective_sample_size(const ChainSet& chains) {
  const ChainSet split = split_chains(chains);
  std::vector<double> all;
  for (const auto& c : split) all.insert(all.end(), c.begin(), c.end());
  return std::min(ess_of_split(indicator(split, quantile(all, 0.05))),
                  ess_of_split(indicator(split, quantile(all, 0.95))));
}

double integrated_autocorrelation_time(const ChainSet& chains) {
  check(chains);
  const double total = static_cast<double>(chains.size() * chains.front().size());
  return total / effective_sample_size(chains);
}

}  // namespace rbcal::calibration
