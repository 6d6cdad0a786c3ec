#include "common/output.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "command.h"
#include "plot_scripts.h"

namespace disklab::cli {
namespace fs = std::filesystem;

std::string fmt17(double value) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

namespace {
fs::path temp_name(const fs::path& target) {
  static std::atomic<int> counter{0};
  // Keep the extension last: matplotlib chooses the format from it.
  fs::path temp = target;
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on the operator+ chain.
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  name += target.extension().string();
  temp.replace_filename(name);
  return temp;
}
}  // namespace

AtomicFile::AtomicFile(fs::path target) : target_(std::move(target)), temp_(temp_name(target_)) {
  if (target_.has_parent_path() && !fs::is_directory(target_.parent_path()))
    throw std::runtime_error("output folder does not exist: " + target_.parent_path().string());
  out_.open(temp_, std::ios::binary);
  if (!out_) throw std::runtime_error("cannot write " + temp_.string());
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void AtomicFile::commit() {
  out_.close();
  if (out_.fail()) throw std::runtime_error("write failed: " + temp_.string());
  fs::rename(temp_, target_);
  committed_ = true;
}

void check_out_file(const std::string& out) {
  const fs::path p(out);
  if (fs::is_directory(p)) throw UsageError("--out: '" + out + "' is a folder, not a file");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir))
    throw UsageError("--out: folder '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError("--out: folder '" + dir.string() + "' is not writable");
}

void write_file_atomic(const fs::path& target, const std::string& content) {
  AtomicFile file(target);
  file.stream() << content;
  file.commit();
}

TempFiles::~TempFiles() {
  std::error_code ec;
  for (const auto& f : files_)
    fs::remove(f, ec);
}

fs::path TempFiles::add(const std::string& stem, const std::string& extension) {
  static std::atomic<int> counter{0};
  fs::path p = fs::temp_directory_path() / ("disklab-" + stem + "-" + std::to_string(::getpid()) +
                                            "-" + std::to_string(counter++) + extension);
  files_.push_back(p);
  return p;
}

Progress::Progress(std::string label, uint64_t total)
    : label_(std::move(label)),
      total_(total),
      tty_(::isatty(STDERR_FILENO) != 0),
      quiet_(std::getenv("DISKLAB_QUIET") != nullptr) {}

Progress::~Progress() {
  finish();
}

void Progress::tick(uint64_t done_now) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  done_ += done_now;
  print(done_);
}

void Progress::print(uint64_t done) {
  if (quiet_ || total_ == 0) return;
  const int decile = static_cast<int>(10 * done / total_);
  if (tty_) {
    std::fprintf(stderr, "\r%s: %llu/%llu", label_.c_str(), static_cast<unsigned long long>(done),
                 static_cast<unsigned long long>(total_));
  } else if (decile != last_decile_) {
    std::fprintf(stderr, "%s: %d%%\n", label_.c_str(), decile * 10);
  }
  last_decile_ = decile;
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!quiet_ && tty_ && total_ > 0) std::fprintf(stderr, "\n");
}

namespace {
std::string_view find_script(const std::string& name) {
  for (const auto& s : embedded::kScripts)
    if (!s.name.empty() && s.name == name) return s.text;
  throw std::runtime_error("no embedded plot script '" + name + "'");
}

std::string python_interpreter() {
  if (const char* env = std::getenv("DISKLAB_PYTHON"); env && *env) return env;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s)
    q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
}  // namespace

void run_plot(const std::string& script, const std::vector<std::string>& args,
              const fs::path& png) {
  const std::string_view text = find_script(script);
  AtomicFile script_file(fs::temp_directory_path() / ("disklab-" + script + ".py"));
  script_file.stream() << text;
  AtomicFile out(png);  // its temporary is where the script writes
  std::ostringstream cmd;
  cmd << shell_quote(python_interpreter()) << ' ' << shell_quote(script_file.temp_path().string())
      << " --out " << shell_quote(out.temp_path().string());
  for (const auto& a : args)
    cmd << ' ' << shell_quote(a);
  script_file.stream().flush();
  const fs::path err =
      fs::temp_directory_path() / ("disklab-plot-" + std::to_string(::getpid()) + ".err");
  cmd << " 2>" << shell_quote(err.string());
  const int status = std::system(cmd.str().c_str());
  std::string message;
  if (std::FILE* f = std::fopen(err.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, f))
      message += buf;
    std::fclose(f);
  }
  std::error_code ec;
  fs::remove(err, ec);
  if (status != 0 || !fs::exists(out.temp_path())) {
    // One line, whatever the script or the shell printed: the CLI's errors are single lines.
    std::string one_line;
    std::size_t start = 0;
    while (start < message.size()) {
      std::size_t end = message.find('\n', start);
      if (end == std::string::npos) end = message.size();
      const std::string line = message.substr(start, end - start);
      if (line.find_first_not_of(" \t\r") != std::string::npos) {
        if (!one_line.empty()) one_line += " | ";
        one_line += line;
      }
      start = end + 1;
    }
    std::string what = "plot script '";
    what += script;
    what += "' failed (needs python3-matplotlib; set DISKLAB_PYTHON to choose the interpreter)";
    if (!one_line.empty()) {
      what += ": ";
      what += one_line;
    }
    throw std::runtime_error(what);
  }
  out.commit();
}

}  // namespace disklab::cli
