// libFuzzer harness: the sweep journal reader on arbitrary file contents (a header line for
// a known fingerprint is prepended half of the time so record lines are reached). Only
// pneumachaos::Error may come out; a file it accepts must hold records that encode and
// decode to the same line.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "journal.hpp"
#include "pneumachaos/core/error.hpp"

namespace {

const std::string& scratch_path() {
  static const std::string path = "/tmp/pneumachaos_fuzz_journal_" + std::to_string(::getpid());
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string fingerprint = "0123456789abcdef";
  std::string text(reinterpret_cast<const char*>(data), size);
  if (size > 0 && (data[0] & 1) != 0) {
    text = pneumachaos::detail::journal_header(fingerprint) + "\n" + text.substr(1);
  }
  {
    std::ofstream out(scratch_path(), std::ios::binary | std::ios::trunc);
    out << text;
  }
  try {
    pneumachaos::detail::JournalReader reader(fingerprint);
    reader.read(scratch_path(), true);
    for (const auto& r : std::move(reader).records()) {
      const std::string line = r.encode();
      if (pneumachaos::RunRecord::decode(line).encode() != line) std::abort();
    }
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
