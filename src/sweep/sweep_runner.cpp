#include "pneumachaos/sweep/sweep_runner.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <thread>

#include "distribution.hpp"
#include "journal.hpp"
#include "pneumachaos/core/error.hpp"
#include "sweep_outputs.hpp"

namespace pneumachaos {

bool sweeps_support_mpi() { return detail::Distribution::built_with_mpi(); }

void SweepOptions::validate() const {
  if (out_dir.empty()) throw Error("--out", "a directory for the results is required");
}

SweepSummary run_sweep(const SweepSpec& spec, const SweepOptions& options) {
  spec.validate();
  options.validate();
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) throw Error(options.out_dir, "cannot create the directory: " + ec.message());
  detail::Distribution& dist = detail::Distribution::instance();
  const std::string own =
      dist.size() == 1 ? "journal.csv" : fmt::format("journal.rank{}.csv", dist.rank());
  // Every rank reads the journals before any rank appends to them.
  dist.barrier();
  detail::Journal journal(options.out_dir, own, spec.fingerprint(), options.resume);
  dist.barrier();

  const std::size_t total = spec.runs();
  std::vector<char> done(total, 0);
  std::vector<RunRecord> records;
  for (const RunRecord& r : journal.existing()) {
    const std::size_t i = r.index(spec.repeats);
    if (r.repeat >= spec.repeats || i >= total)
      throw Error(options.out_dir, "the journal holds a run outside the grid");
    if (done[i]) continue;  // a duplicate line cannot arise, but must not count twice
    done[i] = 1;
    records.push_back(r);
  }
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < total; ++i) {
    // Under MPI each rank takes the runs whose index matches its rank.
    if (!done[i] &&
        i % static_cast<std::size_t>(dist.size()) == static_cast<std::size_t>(dist.rank())) {
      pending.push_back(i);
    }
  }

  const std::size_t hardware = std::max<std::size_t>(
      1, std::thread::hardware_concurrency() / static_cast<std::size_t>(dist.size()));
  const std::size_t threads =
      std::max<std::size_t>(1, std::min(options.threads > 0 ? options.threads : hardware,
                                        std::max<std::size_t>(pending.size(), 1)));
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::size_t finished = 0;
  const bool show = options.progress && ::isatty(STDERR_FILENO) != 0;
  const auto started = std::chrono::steady_clock::now();
  auto last_shown = started;
  std::exception_ptr failure;
  const auto worker = [&] {
    for (std::size_t k = next++; k < pending.size(); k = next++) {
      const std::size_t i = pending[k];
      RunRecord r = run_one(spec, i / spec.repeats, i % spec.repeats);
      std::lock_guard<std::mutex> lock(mutex);
      if (failure) return;
      try {
        journal.append(r);
      } catch (...) {
        failure = std::current_exception();
        return;
      }
      records.push_back(std::move(r));
      ++finished;
      const auto now = std::chrono::steady_clock::now();
      if (show &&
          (now - last_shown > std::chrono::milliseconds(200) || finished == pending.size())) {
        last_shown = now;
        const double elapsed = std::chrono::duration<double>(now - started).count();
        const double rate = finished / std::max(elapsed, 1e-9);
        fmt::print(stderr, "\rsweep: {}/{} runs, {:.1f} runs/s, ETA {:.0f} s   ",
                   total - pending.size() + finished, total, rate,
                   (pending.size() - finished) / std::max(rate, 1e-9));
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (show) fmt::print(stderr, "\n");
  if (failure) std::rethrow_exception(failure);
  if (dist.size() > 1) {
    // Every rank's runs are in its journal once all have arrived here; rank 0 writes.
    dist.barrier();
    records.clear();
    std::vector<char> seen(total, 0);
    for (RunRecord& r : detail::Journal::read_all(options.out_dir, spec.fingerprint())) {
      const std::size_t i = r.index(spec.repeats);
      if (i < total && !seen[i]) {
        seen[i] = 1;
        records.push_back(std::move(r));
      }
    }
    if (records.size() != total) throw Error(options.out_dir, "the ranks' journals are incomplete");
  }

  std::sort(records.begin(), records.end(), [&](const RunRecord& a, const RunRecord& b) {
    return a.index(spec.repeats) < b.index(spec.repeats);
  });
  SweepSummary summary = summarize(spec, records);
  summary.wrote_files = dist.rank() == 0;
  if (summary.wrote_files) detail::write_sweep_outputs(spec, records, summary, options.out_dir);
  dist.barrier();
  return summary;
}

}  // namespace pneumachaos
