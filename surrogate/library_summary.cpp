#include "surrogate/library_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace rbcal::surrogate {

namespace {

bool close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<double> unique_sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end(), close), v.end());
  return v;
}

std::string fmt(double v, const char* spec = "%.4g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

}  // namespace

LibrarySummary summarise(const SimulationLibrary& library) {
  LibrarySummary s;
  s.root = library.root.string();
  s.case_count = library.cases.size();
  if (library.cases.empty()) return s;
  for (const LibraryCase& c : library.cases)
    if (!c.raw_results.empty()) s.extrapolated.push_back(c);
  const LibraryCase& c0 = library.cases.front();
  s.nominal_range = {c0.phi, c0.phi, c0.capillary_number, c0.capillary_number, c0.viscosity_ratio, c0.viscosity_ratio};
  s.phi_actual_min = s.phi_actual_max = c0.phi_actual;
  s.eta_re_min = s.eta_re_max = c0.eta_re;
  std::vector<double> sem, relative_sem, phis, cas, lambdas;
  for (const LibraryCase& c : library.cases) {
    ParameterRange& r = s.nominal_range;
    r.phi_min = std::min(r.phi_min, c.phi), r.phi_max = std::max(r.phi_max, c.phi);
    r.ca_min = std::min(r.ca_min, c.capillary_number), r.ca_max = std::max(r.ca_max, c.capillary_number);
    r.lambda_min = std::min(r.lambda_min, c.viscosity_ratio), r.lambda_max = std::max(r.lambda_max, c.viscosity_ratio);
    s.phi_actual_min = std::min(s.phi_actual_min, c.phi_actual);
    s.phi_actual_max = std::max(s.phi_actual_max, c.phi_actual);
    s.eta_re_min = std::min(s.eta_re_min, c.eta_re);
    s.eta_re_max = std::max(s.eta_re_max, c.eta_re);
    s.total_wall_seconds += c.wall_seconds;
    sem.push_back(c.eta_re_sem);
    relative_sem.push_back(c.eta_re_sem / c.eta_re);
    phis.push_back(c.phi), cas.push_back(c.capillary_number), lambdas.push_back(c.viscosity_ratio);
  }
  s.median_eta_re_sem = median(sem);
  s.median_relative_eta_re_sem = median(relative_sem);

  s.grid_from_plan = library.plan.has_value();
  s.listed_design = s.grid_from_plan && library.plan->is_listed();
  const ParameterGrid grid = s.grid_from_plan ? *library.plan : ParameterGrid{phis, cas, lambdas, {}};
  s.grid = {unique_sorted(grid.phi), unique_sorted(grid.capillary_number), unique_sorted(grid.viscosity_ratio), {}};
  // Grid points phi-major, lambda fastest (the order the tables read); a listed design's in its order.
  std::vector<ParameterPoint> points;
  const std::size_t spanned = s.grid.phi.size() * s.grid.capillary_number.size() * s.grid.viscosity_ratio.size();
  if (s.listed_design) {
    points = library.plan->listed;
  } else if (!s.grid_from_plan && spanned > 2 * library.cases.size()) {
    // No plan, and the cases' values do not fill a grid (a space-filling design, or a library
    // extrapolated from one): list the cases themselves instead of a mostly empty grid.
    s.listed_design = true;
    for (const LibraryCase& c : library.cases) points.push_back({c.phi, c.capillary_number, c.viscosity_ratio});
  } else {
    for (double phi : s.grid.phi)
      for (double ca : s.grid.capillary_number)
        for (double lambda : s.grid.viscosity_ratio) points.push_back({phi, ca, lambda});
  }
  std::vector<bool> matched(library.cases.size(), false);
  for (const ParameterPoint& point : points) {
    GridPoint p{point, false};
    for (std::size_t i = 0; i < library.cases.size(); ++i) {
      const LibraryCase& c = library.cases[i];
      if (close(c.phi, p.phi) && close(c.capillary_number, p.capillary_number) &&
          close(c.viscosity_ratio, p.viscosity_ratio)) {
        p.present = true;
        p.eta_re = c.eta_re;
        matched[i] = true;
      }
    }
    if (!p.present) ++s.missing_count;
    s.grid_points.push_back(p);
  }
  s.off_grid_count = static_cast<std::size_t>(std::count(matched.begin(), matched.end(), false));
  return s;
}

std::string format_summary(const LibrarySummary& s, bool values) {
  std::ostringstream o;
  o << "library " << s.root << "\n"
    << "  cases            " << s.case_count << "\n";
  if (s.case_count == 0) return o.str();
  const ParameterRange& r = s.nominal_range;
  o << "  phi (nominal)    " << fmt(r.phi_min) << " .. " << fmt(r.phi_max) << "  (actual " << fmt(s.phi_actual_min)
    << " .. " << fmt(s.phi_actual_max) << ")\n"
    << "  Ca               " << fmt(r.ca_min) << " .. " << fmt(r.ca_max) << "\n"
    << "  lambda           " << fmt(r.lambda_min) << " .. " << fmt(r.lambda_max) << "\n"
    << "  eta_re           " << fmt(s.eta_re_min) << " .. " << fmt(s.eta_re_max) << "\n"
    << "  median SEM       " << fmt(s.median_eta_re_sem) << " (" << fmt(100.0 * s.median_relative_eta_re_sem, "%.3g")
    << " % of eta_re)\n"
    << "  wall time        " << fmt(s.total_wall_seconds, "%.1f") << " s (" << fmt(s.total_wall_seconds / 3600.0, "%.2f")
    << " h)\n"
    << "  grid (" << (s.grid_from_plan ? "plan.json" : "values present") << ")  ";
  if (s.listed_design)
    o << "listed design of " << s.grid_points.size() << " points";
  else
    o << s.grid.phi.size() << " phi x " << s.grid.capillary_number.size() << " Ca x " << s.grid.viscosity_ratio.size()
      << " lambda = " << s.grid_points.size() << " points";
  o << ", " << s.grid_points.size() - s.missing_count << " present, " << s.missing_count << " missing";
  if (s.grid_from_plan) o << ", " << s.off_grid_count << " cases off the plan's grid";
  o << "\n";
  if (s.listed_design) {
    // One line per design point: the tables below need a grid.
    for (const GridPoint& g : s.grid_points)
      o << "  " << fmt(g.phi, "phi %-6.3g") << fmt(g.capillary_number, " Ca %-7.3g") << fmt(g.viscosity_ratio, " lambda %-6.3g")
        << (g.present ? (values ? fmt(g.eta_re, "  eta_re %.4g") : std::string("  x")) : std::string("  . missing")) << "\n";
  }
  // One table per lambda: rows phi, columns Ca; 'x' present, '.' missing.
  const std::size_t n_ca = s.grid.capillary_number.size(), n_lambda = s.listed_design ? 0 : s.grid.viscosity_ratio.size();
  for (std::size_t l = 0; l < n_lambda; ++l) {
    o << "\n  lambda = " << fmt(s.grid.viscosity_ratio[l])
      << (values ? "   (eta_re, . missing)\n          " : "   (x present, . missing)\n          ");
    for (double ca : s.grid.capillary_number) o << fmt(ca, " %7.3g");
    o << "   <- Ca\n";
    for (std::size_t p = 0; p < s.grid.phi.size(); ++p) {
      o << "  phi " << fmt(s.grid.phi[p], "%-4.3g");
      for (std::size_t c = 0; c < n_ca; ++c) {
        const GridPoint& g = s.grid_points[(p * n_ca + c) * n_lambda + l];
        if (values)
          o << (g.present ? fmt(g.eta_re, " %7.3g") : std::string("       ."));
        else
          o << "       " << (g.present ? 'x' : '.');
      }
      o << "\n";
    }
  }
  if (!s.extrapolated.empty()) {
    // Raw values per resolution next to the extrapolated one (the grid above shows the latter).
    o << "\n  extrapolated to the continuum (raw eta_re +- sem per N_a; extrapolated +- sd; method)\n";
    for (const LibraryCase& c : s.extrapolated) {
      o << "  " << fmt(c.phi, "phi %-6.3g") << fmt(c.capillary_number, " Ca %-7.3g") << fmt(c.viscosity_ratio, " lambda %-6.3g");
      for (const ResolutionResult& raw : c.raw_results)
        o << "  N_a " << raw.nodes_per_radius << fmt(raw.eta_re, " %7.4g") << fmt(raw.eta_re_sem, " +- %-6.2g");
      if (c.raw_results.size() == 1) o << std::string(25, ' ');
      o << "  -> " << fmt(c.eta_re, "%7.4g") << fmt(c.eta_re_sem, " +- %-6.2g") << "  " << c.extrapolation_method;
      if (c.phi_as_run > 0.0) o << fmt(c.phi_as_run, " (run at phi %.4g)");
      o << "\n";
    }
  }
  return o.str();
}

}  // namespace rbcal::surrogate
