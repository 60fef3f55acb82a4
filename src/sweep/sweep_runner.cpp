#include "pneumachaos/sweep/sweep_runner.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>

#include <tbb/task_arena.h>

#include "pneumachaos/sweep/distribution.hpp"
#include "journal.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/model/variation.hpp"
#include "sweep/grid_refinement.hpp"
#include "core/parallel_indices.hpp"
#include "sweep_outputs.hpp"

namespace pneumachaos {

bool sweeps_support_mpi() { return detail::Distribution::built_with_mpi(); }

void SweepOptions::validate() const {
  if (out_dir.empty())
    throw Error(validation::field("sweep.out_dir"), "", "name the sweep's output directory");
}

namespace {

// Runs on one rank may throw; every rank must still reach each collective step, so a
// failure is held until all ranks have agreed that one happened, then rethrown.
class RankFailure {
 public:
  template <typename F>
  void attempt(F&& f) {
    if (failure_) return;
    try {
      f();
    } catch (...) {
      failure_ = std::current_exception();
    }
  }
  void agree(const detail::Distribution& dist, const std::string& dir) {
    const bool all_ok = dist.all_ok(!failure_);
    if (failure_) std::rethrow_exception(failure_);
    if (!all_ok) throw RunError(dir, "another MPI rank failed; its message says why");
  }

 private:
  std::exception_ptr failure_;
};

// Indices of the runs the journal already holds; a run outside the grid means the journal
// does not belong to this grid.
std::vector<char> finished_runs(const SweepSpec& spec, const std::vector<RunRecord>& existing,
                                const std::string& dir) {
  std::vector<char> done(spec.runs(), 0);
  for (const RunRecord& r : existing) {
    const std::size_t i = r.index(spec.repeats);
    if (r.repeat >= spec.repeats || i >= done.size())
      throw Error(dir, "the journal holds a run outside the grid");
    done[i] = 1;
  }
  return done;
}

// Under MPI each rank takes the runs whose index matches its rank.
std::vector<std::size_t> pending_runs(const std::vector<char>& done,
                                      const detail::Distribution& dist) {
  std::vector<std::size_t> pending;
  const auto ranks = static_cast<std::size_t>(dist.size());
  for (std::size_t i = 0; i < done.size(); ++i) {
    if (!done[i] && i % ranks == static_cast<std::size_t>(dist.rank())) pending.push_back(i);
  }
  return pending;
}

std::size_t thread_count(std::size_t requested, std::size_t work,
                         const detail::Distribution& dist) {
  const std::size_t hardware = std::max<std::size_t>(
      1, std::thread::hardware_concurrency() / static_cast<std::size_t>(dist.size()));
  return std::max<std::size_t>(
      1, std::min(requested > 0 ? requested : hardware, std::max<std::size_t>(work, 1)));
}

// run_one turns bad input into a failed record; anything else it lets escape (a bug, memory
// exhaustion) becomes a failed record here too, so a worker thread never terminates the
// process and the other runs are kept.
RunRecord guarded_run(const SweepSpec& spec, std::size_t i, const SweepOptions& options) {
  try {
    return run_one(spec, i / spec.repeats, i % spec.repeats, options.on_run);
  } catch (const std::exception& e) {
    RunRecord r;
    r.point = i / spec.repeats;
    r.repeat = i % spec.repeats;
    r.seed = run_seed(spec.seed, r.point, r.repeat);
    r.ok = false;
    r.reason = std::string("internal error: ") + e.what();
    return r;
  }
}

class Progress {
 public:
  Progress(bool show, std::size_t total, std::size_t already)
      : show_(show), total_(total), already_(already) {}
  void update(std::size_t finished, std::size_t pending) {
    const auto now = std::chrono::steady_clock::now();
    if (!show_ || (now - last_ < std::chrono::milliseconds(200) && finished != pending)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - started_).count();
    const double rate = finished / std::max(elapsed, 1e-9);
    fmt::print(stderr, "\rsweep: {}/{} runs, {:.1f} runs/s, ETA {:.0f} s   ",
               already_ + finished, total_, rate, (pending - finished) / std::max(rate, 1e-9));
  }
  ~Progress() {
    if (show_) fmt::print(stderr, "\n");
  }

 private:
  bool show_;
  std::size_t total_, already_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_{};
};

// Runs `pending` on threads, journaling each finished run; stops taking new runs after the
// journal fails and rethrows that failure. `total`: the sweep's runs known so far, for the
// progress (an adaptive sweep learns its total round by round).
void run_pending(const SweepSpec& spec, const SweepOptions& options,
                 const std::vector<std::size_t>& pending, std::size_t total,
                 detail::Journal& journal, std::vector<RunRecord>& records,
                 const detail::Distribution& dist) {
  std::mutex mutex;
  std::size_t finished = 0;
  std::exception_ptr failure;
  Progress progress(options.progress && ::isatty(STDERR_FILENO) != 0, total,
                    total - pending.size());
  std::atomic<bool> stop{false};
  const auto one = [&](std::size_t k) {
    if (stop) return;  // the journal failed: take no new runs
    RunRecord r = guarded_run(spec, pending[k], options);
    std::lock_guard<std::mutex> lock(mutex);
    if (failure) return;
    try {
      journal.append(r);
    } catch (...) {
      failure = std::current_exception();
      stop = true;
      return;
    }
    records.push_back(std::move(r));
    progress.update(++finished, pending.size());
    if (options.on_progress) options.on_progress(total - pending.size() + finished, total);
  };
  // oneTBB's work-stealing scheduler, limited to the requested threads by an arena; one run
  // per task (grain 1), as runs differ in cost by an order of magnitude.
  const auto threads = static_cast<int>(thread_count(options.threads, pending.size(), dist));
  tbb::task_arena arena(threads);
  arena.execute([&] { detail::parallel_indices(pending.size(), one); });
  if (failure) std::rethrow_exception(failure);
  journal.sync();
}

// What an adaptive map tells apart at an evaluated point: the stick-slip region, the chaos
// class, whether any run failed and, when asked, whether the motion settles (the paper's
// damped / self-excited, which the report's sign rule reads); a cell whose points differ in
// it is refined.
int map_class(const PointSummary& p, bool follow_motion) {
  return (in_stick_slip_region(p) ? 1 : 0) + 2 * static_cast<int>(chaos_class(p)) +
         (p.failed > 0 ? 8 : 0) + (follow_motion ? 16 * static_cast<int>(point_motion(p)) : 0);
}

// The runs of `points` that are not finished yet and fall to this rank.
std::vector<std::size_t> pending_at(const SweepSpec& spec, const std::vector<std::size_t>& points,
                                    const std::vector<RunRecord>& records, const std::string& dir,
                                    const detail::Distribution& dist) {
  std::vector<char> done = finished_runs(spec, records, dir);
  std::vector<char> wanted(done.size(), 0);
  for (std::size_t p : points)
    for (std::size_t r = 0; r < spec.repeats; ++r) wanted[p * spec.repeats + r] = 1;
  for (std::size_t i = 0; i < done.size(); ++i) done[i] = done[i] != 0 || wanted[i] == 0;
  return pending_runs(done, dist);
}

// The refinement's rounds, each a batch of points run on threads (and ranks): every rank
// derives the same batches from the same records, so it needs every rank's records after each
// round. A resume replays the rounds, running only what the journals lack. Returns where
// every point takes its class from.
std::vector<std::size_t> run_adaptive(const SweepSpec& spec, const SweepOptions& options,
                                      detail::Journal& journal, std::vector<RunRecord>& records,
                                      const detail::Distribution& dist, RankFailure& failure) {
  GridRefinement grid(spec.axes[0].values.size(), spec.axes[1].values.size(),
                      spec.adaptive.coarse_step);
  std::vector<int> classes(spec.points(), 0);
  for (;;) {
    std::vector<std::size_t> batch;
    failure.attempt([&] {
      batch = grid.next(classes);
      const auto pending = pending_at(spec, batch, records, options.out_dir, dist);
      run_pending(spec, options, pending, records.size() + pending.size(), journal, records,
                  dist);
    });
    failure.agree(dist, options.out_dir);
    if (batch.empty()) return grid.sources();
    failure.attempt([&] {
      if (dist.size() > 1) records = detail::Journal::read_all(options.out_dir, spec.fingerprint());
      const SweepSummary so_far = summarize(spec, records);
      for (std::size_t p : batch)
        classes[p] = map_class(so_far.per_point[p], spec.adaptive.follow_motion);
    });
    failure.agree(dist, options.out_dir);
  }
}

// Every rank's runs are in its journal once all have finished; read them all back.
std::vector<RunRecord> merged_records(const SweepSpec& spec, const std::string& dir) {
  std::vector<RunRecord> records = detail::Journal::read_all(dir, spec.fingerprint());
  if (records.size() != spec.runs()) throw RunError(dir, "the ranks' journals are incomplete");
  return records;
}

}  // namespace

SweepSummary run_sweep(const SweepSpec& spec, const SweepOptions& options) {
  spec.validate();
  options.validate();
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) throw Error(options.out_dir, "cannot create the directory: " + ec.message());
  detail::Distribution& dist = detail::Distribution::instance();
  const std::string own =
      dist.size() == 1 ? "journal.csv" : fmt::format("journal.rank{}.csv", dist.rank());
  RankFailure failure;
  std::unique_ptr<detail::Journal> journal;
  std::vector<RunRecord> records;
  failure.attempt([&] {
    journal = std::make_unique<detail::Journal>(options.out_dir, own, spec.fingerprint(),
                                                options.resume);
    records = journal->existing();
  });
  // Every rank has read the directory before any rank creates its own journal in it.
  failure.agree(dist, options.out_dir);
  failure.attempt([&] { journal->open(); });
  failure.agree(dist, options.out_dir);
  std::vector<std::size_t> sources;
  if (spec.adaptive.enabled) {
    sources = run_adaptive(spec, options, *journal, records, dist, failure);
  } else {
    failure.attempt([&] {
      const auto pending = pending_runs(finished_runs(spec, records, options.out_dir), dist);
      run_pending(spec, options, pending, spec.runs(), *journal, records, dist);
    });
    failure.agree(dist, options.out_dir);
  }
  SweepSummary summary;
  failure.attempt([&] {
    // An adaptive sweep has read every rank's records after its last round.
    if (dist.size() > 1 && !spec.adaptive.enabled) records = merged_records(spec, options.out_dir);
    std::sort(records.begin(), records.end(), [&](const RunRecord& a, const RunRecord& b) {
      return a.index(spec.repeats) < b.index(spec.repeats);
    });
    summary = spec.adaptive.enabled ? summarize_adaptive(spec, records, sources)
                                    : summarize(spec, records);
    summary.wrote_files = dist.rank() == 0;
    if (summary.wrote_files) detail::write_sweep_outputs(spec, records, summary, options.out_dir);
  });
  failure.agree(dist, options.out_dir);
  return summary;
}

}  // namespace pneumachaos
