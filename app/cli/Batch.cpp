#include "app/cli/Batch.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace armtrack::cli {

namespace {

using Clock = std::chrono::steady_clock;

// What the pool threads share with the thread that draws the progress.
struct Shared {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::size_t> finished;  // jobs ended since the display last looked, in order
  std::size_t running = 0;            // pool threads not yet done
};

std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

}  // namespace

unsigned defaultBatchThreads() {
  return std::max(1u, std::thread::hardware_concurrency());
}

bool isTerminal(const std::ostream& err) {
  return &err == &std::cerr && ::isatty(STDERR_FILENO) == 1;
}

std::vector<BatchOutcome> runBatch(const std::vector<BatchJob>& jobs, unsigned threads,
                                   const BatchWork& work, const BatchDisplay& display) {
  return runBatch(jobs, threads, BatchWorkFactory([&work] { return work; }), display);
}

std::vector<BatchOutcome> runBatch(const std::vector<BatchJob>& jobs, unsigned threads,
                                   const BatchWorkFactory& makeWork, const BatchDisplay& display) {
  const std::size_t n = jobs.size();
  std::vector<BatchOutcome> outcomes(n);
  if (n == 0) return outcomes;
  // Progress of each job in millionths, written by its thread, read by the display.
  const auto progress = std::make_unique<std::atomic<std::uint32_t>[]>(n);
  for (std::size_t i = 0; i < n; ++i) progress[i].store(0, std::memory_order_relaxed);
  std::uint64_t totalWeight = 0;
  for (const BatchJob& j : jobs) totalWeight += std::max<std::uint64_t>(j.weight, 1);

  Shared shared;
  std::atomic<std::size_t> next{0};
  const unsigned poolSize = static_cast<unsigned>(std::min<std::size_t>(std::max(threads, 1u), n));
  shared.running = poolSize;
  const auto worker = [&] {
    BatchWork work;
    std::string setupError;
    try {
      work = makeWork();
    } catch (const std::exception& e) {
      setupError = oneLine(e.what());
    } catch (...) {
      setupError = "unexpected failure";
    }
    if (!work && setupError.empty()) setupError = "the batch's thread has no work";
    for (std::size_t i; (i = next.fetch_add(1)) < n;) {
      const auto start = Clock::now();
      BatchOutcome& o = outcomes[i];
      try {
        if (!work) throw std::runtime_error(setupError);
        work(i, [&progress, i](double f) {
          const double c = std::clamp(f, 0.0, 1.0);
          progress[i].store(static_cast<std::uint32_t>(c * 1e6), std::memory_order_relaxed);
        });
        o.ok = true;
      } catch (const std::exception& e) {
        o.error = oneLine(e.what());
      } catch (...) {
        o.error = "unexpected failure";
      }
      o.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      progress[i].store(1000000, std::memory_order_relaxed);
      const std::lock_guard lock(shared.mutex);
      shared.finished.push_back(i);
      shared.changed.notify_one();
    }
    work = nullptr;  // what makeWork made ends on this thread
    const std::lock_guard lock(shared.mutex);
    --shared.running;
    shared.changed.notify_one();
  };
  std::vector<std::thread> pool;
  pool.reserve(poolSize);
  for (unsigned t = 0; t < poolSize; ++t) pool.emplace_back(worker);

  std::ostream* err = display.err;
  const std::string prefix = display.prefix.empty() ? "" : display.prefix + ": ";
  std::size_t done = 0, failed = 0;
  bool lineDrawn = false;
  const auto clearLine = [&] {
    if (lineDrawn) *err << "\r\033[K";
    lineDrawn = false;
  };
  for (bool more = true; more;) {
    std::vector<std::size_t> ended;
    {
      std::unique_lock lock(shared.mutex);
      shared.changed.wait_for(lock, std::chrono::milliseconds(250),
                              [&] { return !shared.finished.empty() || shared.running == 0; });
      ended.swap(shared.finished);
      more = shared.running > 0;
    }
    if (!err) continue;
    for (const std::size_t i : ended) {
      ++done;
      const BatchOutcome& o = outcomes[i];
      failed += !o.ok;
      if (display.terminal && o.ok) continue;
      clearLine();
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.1f", o.seconds);
      *err << prefix << "[" << done << "/" << n << "] " << jobs[i].name << ": "
           << (o.ok ? "done in " + std::string(seconds) + " s" : "failed: " + o.error) << "\n";
    }
    if (display.terminal) {
      double weighted = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        weighted += static_cast<double>(std::max<std::uint64_t>(jobs[i].weight, 1)) *
                    progress[i].load(std::memory_order_relaxed) / 1e6;
      char line[160];
      std::snprintf(line, sizeof line, "\r\033[K%sprogress: %zu of %zu done (%zu failed), %.0f%%",
                    prefix.c_str(), done, n, failed,
                    100.0 * weighted / static_cast<double>(totalWeight));
      *err << line << std::flush;
      lineDrawn = true;
    }
  }
  for (std::thread& t : pool) t.join();
  if (err) {
    clearLine();
    err->flush();
  }
  return outcomes;
}

}  // namespace armtrack::cli
