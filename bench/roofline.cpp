#include "bench/roofline.hpp"

#include <omp.h>

#include "bench/host_description.hpp"
#include "bench/lattice_throughput.hpp"
#include "bench/detail/stream_triad.hpp"
#include "bench/detail/timing.hpp"

namespace rbcal::bench {

RooflineResult measure_roofline(const RooflineSettings& settings) {
  StreamTriad triad(settings.triad_elements);
  LatticeThroughput lattice(settings.box, settings.single_precision, settings.prefetch_distance);
  triad.run_once(false);  // warm-up
  triad.run_once(true);

  RooflineResult r;
  r.threads = omp_get_max_threads();
  std::vector<double> ratio, ratio_streaming;
  for (int round = 0; round < settings.rounds; ++round) {
    r.triad_bytes_per_s.push_back(triad.bytes_counted() / triad.run_once(false));
    r.triad_streaming_bytes_per_s.push_back(triad.bytes_counted() / triad.run_once(true));
    r.lattice_updates_per_s.push_back(lattice.nodes() * settings.steps / lattice.run_once(settings.steps));
    const double lattice_bytes =
        r.lattice_updates_per_s.back() * (settings.single_precision ? LatticeThroughput::bytes_per_update_single
                                                                     : LatticeThroughput::bytes_per_update);
    ratio.push_back(lattice_bytes / r.triad_bytes_per_s.back());
    ratio_streaming.push_back(lattice_bytes / r.triad_streaming_bytes_per_s.back());
  }
  const MemoryUse use = memory_use();
  r.anonymous_bytes = use.anonymous_bytes;
  r.huge_page_bytes = use.huge_page_bytes;
  r.median_triad = median(r.triad_bytes_per_s);
  r.median_triad_streaming = median(r.triad_streaming_bytes_per_s);
  r.median_updates = median(r.lattice_updates_per_s);
  r.fraction_of_triad = median(ratio);
  r.fraction_of_streaming_triad = median(ratio_streaming);
  return r;
}

}  // namespace rbcal::bench
