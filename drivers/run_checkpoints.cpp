#include "drivers/run_checkpoints.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "io/build_id.hpp"

namespace granmc {

namespace {

// Set by the first SIGINT or SIGTERM; a second one ends the process at once (the default action).
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_stop_signal(int signal) {
  stop_requested.store(true);
  std::signal(signal, SIG_DFL);
}

/// BASE when `name` is BASE.K-of-R (K and R decimal digits), else nothing.
std::optional<std::string> rank_file_base(const std::string& name) {
  const std::size_t of = name.rfind("-of-");
  const std::size_t dot = of == std::string::npos ? std::string::npos : name.rfind('.', of);
  if (dot == std::string::npos) return std::nullopt;
  const auto digits = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  const std::string_view whole(name);
  if (!digits(whole.substr(dot + 1, of - dot - 1)) || !digits(whole.substr(of + 4))) return std::nullopt;
  return name.substr(0, dot);
}

}  // namespace

std::string checkpoint_path(const std::string& hdf5) { return hdf5 + ".checkpoint"; }

std::string checkpoint_file(const std::string& base, int rank, int ranks) {
  if (ranks == 1) return base;
  return base + "." + std::to_string(rank) + "-of-" + std::to_string(ranks);
}

std::vector<std::string> checkpoint_files(const std::string& path) {
  const std::string base = rank_file_base(path).value_or(path);
  const std::filesystem::path dir = std::filesystem::path(base).parent_path();
  const std::string name = std::filesystem::path(base).filename().string();
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir.empty() ? "." : dir, error)) {
    const std::string file = entry.path().filename().string();
    if (file == name || rank_file_base(file) == name) files.push_back((dir / file).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

RunCheckpoints::RunCheckpoints(const Scene& scene, const std::string& hdf5, const CheckpointSettings& settings,
                               int rank, int ranks)
    : settings_(settings),
      base_(checkpoint_path(hdf5)),
      path_(checkpoint_file(base_, rank, ranks)),
      started_(std::chrono::steady_clock::now()),
      last_write_(started_) {
  checkpoint_.build = build_id();
  checkpoint_.scene_text = scene.source_text;
  checkpoint_.seed = scene.run.seed;
  checkpoint_.replicas = static_cast<std::uint64_t>(scene.run.replicas);
  if (!settings_.resume.empty()) {
    const std::vector<std::string> files = checkpoint_files(settings_.resume);
    if (files.empty()) read_checkpoint(settings_.resume);  // throws: the file is missing
    for (const std::string& file : files) {
      Checkpoint earlier = read_checkpoint(file);
      const std::string why = checkpoint_mismatch(earlier, checkpoint_.build, checkpoint_.scene_text, checkpoint_.seed,
                                                  checkpoint_.replicas);
      if (!why.empty()) throw CheckpointError("cannot resume from '" + file + "': " + why);
      merge_checkpoint(checkpoint_, std::move(earlier));
    }
    restored_all_ = checkpoint_.finished.size();
    restored_in_flight_all_ = checkpoint_.in_flight.size();
    // This rank keeps its own replicas (RunOptions offset = rank, stride = ranks), and writes only those.
    const auto others = [&](const auto& entry) { return static_cast<int>(entry.first % ranks) != rank; };
    std::erase_if(checkpoint_.finished, others);
    std::erase_if(checkpoint_.in_flight, others);
    restored_ = checkpoint_.finished.size();
    restored_in_flight_ = checkpoint_.in_flight.size();
    for (const auto& [r, state] : checkpoint_.in_flight) restored_samples_ += state.samples_taken;
  }
  if (settings_.enabled) {
    stop_requested.store(false);
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
  }
}

RunCheckpoints::~RunCheckpoints() {
  if (settings_.enabled) {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
}

void RunCheckpoints::attach(RunOptions& options) {
  // The restored replicas are read only while the run lasts; on_replica adds others under the mutex, and a
  // std::map's existing elements stay where they are.
  options.restored = [this](std::uint64_t r) -> const ReplicaSeries* {
    const std::lock_guard lock(mutex_);
    const auto at = checkpoint_.finished.find(r);
    return at == checkpoint_.finished.end() ? nullptr : &at->second;
  };
  options.restored_in_flight = [this](std::uint64_t r) -> const ReplicaInFlight* {
    const std::lock_guard lock(mutex_);
    const auto at = checkpoint_.in_flight.find(r);
    return at == checkpoint_.in_flight.end() ? nullptr : &at->second;
  };
  if (!settings_.enabled) return;
  options.on_replica = [this](std::uint64_t r, const ReplicaSeries& series) {
    const std::lock_guard lock(mutex_);
    checkpoint_.finished.emplace(r, series);
    checkpoint_.in_flight.erase(r);
    write_if_due_locked();
  };
  options.in_flight_wanted = [this](std::uint64_t r) {
    if (stop_requested.load() || settings_.every_minutes == 0.0) return true;
    const std::lock_guard lock(mutex_);
    const auto at = last_in_flight_.find(r);
    return minutes_since(at == last_in_flight_.end() ? started_ : at->second) >= settings_.every_minutes;
  };
  options.on_in_flight = [this](std::uint64_t r, ReplicaInFlight&& state) {
    const std::lock_guard lock(mutex_);
    checkpoint_.in_flight.insert_or_assign(r, std::move(state));
    last_in_flight_[r] = std::chrono::steady_clock::now();
    write_if_due_locked();
  };
  options.interrupted = [] { return stop_requested.load(); };
  options.on_sample = [tick = std::move(options.on_sample)] {
    if (tick) tick();
    if (stop_requested.load()) throw RunInterrupted();
  };
}

const std::string& RunCheckpoints::write_now() {
  const std::lock_guard lock(mutex_);
  write_locked();
  return path_;
}

void RunCheckpoints::write_locked() {
  write_checkpoint(path_, checkpoint_);
  last_write_ = std::chrono::steady_clock::now();
}

void RunCheckpoints::write_if_due_locked() {
  if (minutes_since(last_write_) < settings_.every_minutes || stop_requested.load()) return;
  write_or_report_locked();
}

void RunCheckpoints::write_or_report_locked() noexcept {
  try {
    write_locked();
  } catch (const std::exception& e) {  // e.g. a full disk: the run goes on, the previous checkpoint stays
    std::cerr << "granmc: " << e.what() << "; the run goes on\n";
    last_write_ = std::chrono::steady_clock::now();  // the next attempt after another interval
  }
}

void RunCheckpoints::write_before_waiting() {
  if (!settings_.enabled) return;
  const std::lock_guard lock(mutex_);
  write_or_report_locked();
}

double RunCheckpoints::minutes_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::ratio<60>>(std::chrono::steady_clock::now() - t).count();
}

void RunCheckpoints::run_completed() {
  std::error_code ignored;
  for (const std::string& file : checkpoint_files(base_)) std::filesystem::remove(file, ignored);
}

std::size_t RunCheckpoints::finished() const {
  const std::lock_guard lock(mutex_);
  return checkpoint_.finished.size();
}

std::size_t RunCheckpoints::in_flight() const {
  const std::lock_guard lock(mutex_);
  return checkpoint_.in_flight.size();
}

}  // namespace granmc
