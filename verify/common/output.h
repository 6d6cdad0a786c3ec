#pragma once
// Output helpers: round-trip number formatting, atomic files, progress on stderr, plots.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace disklab::cli {

// %.17g: enough digits to read the same double back.
std::string fmt17(double value);

// Writes to a temporary file next to `target` and renames it into place on commit(); if the
// object dies uncommitted (an error), the temporary is removed and `target` is untouched.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  // Path of the temporary, for a producer that writes the file itself (e.g. a plot script).
  const std::filesystem::path& temp_path() const { return temp_; }
  void commit();

 private:
  std::filesystem::path target_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

// --out naming a file: it must not be a folder and its folder must exist and be writable.
// Checked before any work so a bad path fails fast (UsageError, exit 2).
void check_out_file(const std::string& out);

// Writes `content` to `target` atomically.
void write_file_atomic(const std::filesystem::path& target, const std::string& content);

// Text streamed to `out` through a buffer written every ~64 KiB: a CSV of millions of rows
// needs no more memory than a chunk. Append to text(), call row_done() after each row; the
// destructor (or flush()) writes the rest.
class ChunkedOutput {
 public:
  explicit ChunkedOutput(std::ostream& out) : out_(out) {}
  ChunkedOutput(const ChunkedOutput&) = delete;
  ChunkedOutput& operator=(const ChunkedOutput&) = delete;
  ~ChunkedOutput() { flush(); }
  std::string& text() { return buf_; }
  void row_done() {
    if (buf_.size() > (std::size_t{1} << 16)) flush();
  }
  void flush() {
    out_ << buf_;
    buf_.clear();
    out_.flush();
  }

 private:
  std::ostream& out_;
  std::string buf_;
};

// Temporary files in the system's temporary folder (inputs of the plot scripts), removed when the
// object dies, whatever happens.
class TempFiles {
 public:
  TempFiles() = default;
  TempFiles(const TempFiles&) = delete;
  TempFiles& operator=(const TempFiles&) = delete;
  ~TempFiles();
  // A new path "disklab-<stem>-<pid>-<k><extension>", removed with this object.
  std::filesystem::path add(const std::string& stem, const std::string& extension = ".csv");

 private:
  std::vector<std::filesystem::path> files_;
};

// Progress of a long run on stderr: a rewritten line on a terminal, a line per ~10% otherwise.
// Thread-safe tick(); silent when DISKLAB_QUIET is set.
class Progress {
 public:
  Progress(std::string label, uint64_t total);
  ~Progress();
  void tick(uint64_t done_now = 1);
  void finish();

 private:
  void print(uint64_t done);
  std::string label_;
  uint64_t total_;
  uint64_t done_ = 0;
  int last_decile_ = -1;
  bool tty_, quiet_, finished_ = false;
};

// Runs the embedded matplotlib script `script` (verify/plots/<script>.py) with the arguments,
// producing the PNG `png` atomically. The interpreter is $DISKLAB_PYTHON, else /usr/bin/python3
// (Debian's, where python3-matplotlib lives), else python3 on PATH.
// Throws std::runtime_error with the script's stderr if it fails.
void run_plot(const std::string& script, const std::vector<std::string>& args,
              const std::filesystem::path& png);

}  // namespace disklab::cli
