#include "journal.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::detail {

namespace {

constexpr const char* kHeaderStart = "# pneumachaos sweep journal, spec ";

// The first line must be this sweep's header; a journal of another sweep and a damaged one
// (no header at all) are refused with different words, since the remedies differ.
void check_header(const std::string& line, const std::string& path,
                  const std::string& fingerprint) {
  if (line == journal_header(fingerprint)) return;
  // Same sweep, other record format (e.g. before the model-exponent columns): say so, since
  // resuming would mix records of two formats.
  const std::string own = journal_header(fingerprint);
  const std::string same_spec = own.substr(0, own.rfind(", ") + 2);
  if (line.rfind(same_spec, 0) == 0) {
    throw Error(path, fmt::format("the journal was written by another version of pneumachaos "
                                  "(records of {}; this version writes {} fields); refusing to "
                                  "resume into it",
                                  line.substr(same_spec.size()), RunRecord::kFields));
  }
  if (line.rfind(kHeaderStart, 0) == 0) {
    throw Error(path,
                "the journal belongs to a different sweep (another scenario, grid, repeats, "
                "seed, --wolf, --surrogates or model-exponent settings) or to another version "
                "of pneumachaos; refusing to resume into it");
  }
  throw Error(fmt::format("{}:1", path),
              "the journal is damaged: its first line is not a pneumachaos journal header; "
              "move it away and run the sweep again");
}

// The text up to the last complete line; `cut` truncates a torn tail in the file too (only
// for the own file: another rank may be writing its tail right now).
std::string complete_lines(const std::string& path, bool cut) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return "";  // open() names the obstacle
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot read the journal");
  std::stringstream text;
  text << in.rdbuf();
  std::string all = text.str();
  const auto last_newline = all.rfind('\n');
  const std::size_t keep = last_newline == std::string::npos ? 0 : last_newline + 1;
  if (keep < all.size()) {
    all.resize(keep);
    if (cut) std::filesystem::resize_file(path, keep);
  }
  return all;
}

}  // namespace

std::string journal_header(const std::string& fingerprint) {
  return fmt::format("{}{}, {} fields", kHeaderStart, fingerprint, RunRecord::kFields);
}

void JournalReader::read(const std::string& path, bool cut) {
  std::istringstream lines(complete_lines(path, cut));
  std::string line;
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    ++n;
    if (n == 1) {
      check_header(line, path, fingerprint_);
      continue;
    }
    const std::string where = fmt::format("{}:{}", path, n);
    RunRecord r;
    try {
      r = RunRecord::decode(line);
    } catch (const Error& e) {
      throw Error(where, e.what());
    }
    // One run is written once; a second copy means two sweeps wrote into one directory.
    const auto [it, fresh] = origin_.emplace(std::make_pair(r.point, r.repeat), where);
    if (!fresh) {
      throw Error(where, fmt::format("point {} repeat {} was already recorded at {}: two "
                                     "sweeps have written into this directory",
                                     r.point, r.repeat, it->second));
    }
    records_.push_back(std::move(r));
  }
}

namespace {

std::vector<std::string> journal_files(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("journal", 0) == 0 && entry.path().extension() == ".csv") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<RunRecord> Journal::read_all(const std::string& dir, const std::string& fingerprint) {
  JournalReader reader(fingerprint);
  for (const auto& f : journal_files(dir)) reader.read(f, false);
  return std::move(reader).records();
}

Journal::Journal(const std::string& dir, const std::string& own_name,
                 const std::string& fingerprint, bool resume)
    : path_((std::filesystem::path(dir) / own_name).string()), fingerprint_(fingerprint) {
  const auto files = journal_files(dir);
  if (!files.empty() && !resume) {
    throw Error(dir,
                "this directory already holds a sweep: add --resume to finish it, or "
                "choose another --out");
  }
  JournalReader reader(fingerprint);
  // Compared by name: "DIR/" and "DIR" must find the same own journal, so its torn tail is cut.
  for (const auto& f : files) reader.read(f, std::filesystem::path(f).filename() == own_name);
  existing_ = std::move(reader).records();
}

void Journal::open() {
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) {
    throw RunError(path_, "a directory stands where the journal must be written");
  }
  const auto size = std::filesystem::file_size(path_, ec);
  const bool fresh = ec || size == 0;
  file_ = std::fopen(path_.c_str(), "ab");
  if (file_ == nullptr) throw RunError(path_, "cannot open the journal for writing");
  if (fresh) write_line(journal_header(fingerprint_) + "\n");
}

Journal::~Journal() {
  if (file_ != nullptr) std::fclose(file_);
}

void Journal::append(const RunRecord& record) { write_line(record.encode() + "\n"); }

// Each line reaches the operating system at once (a killed process loses no finished run);
// the disk is forced at most once per kSyncInterval and by sync(). An fsync costs ~5 ms here,
// as much as a seventh of a run, and ran under the sweep's lock: one per run held the other
// worker waiting (docs/sweep.md, "Interruption and resume").
void Journal::write_line(const std::string& line) {
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0) {
    throw RunError(path_, "cannot append to the journal (disk full?)");
  }
  if (std::chrono::steady_clock::now() - synced_ >= kSyncInterval) sync();
}

void Journal::sync() {
  if (::fsync(::fileno(file_)) != 0) throw RunError(path_, "cannot sync the journal to disk");
  synced_ = std::chrono::steady_clock::now();
}

}  // namespace pneumachaos::detail
