#include "support/spin.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

namespace rearm::test_support {
namespace {

// Exit status of coreutils `timeout` when the bound expired.
constexpr int kTimeoutExitCode = 124;
// Grace period after SIGTERM before `timeout` sends SIGKILL.
constexpr const char* kKillAfter = "1";

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate =
        (dir.empty() ? std::filesystem::current_path() : std::filesystem::path(dir)) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

bool spin_installed() { return on_path("spin") && on_path("timeout"); }

SpinRun run_spin(const ltl::Formula& f, double timeout_seconds) {
  SpinRun run;
  const std::string formula = f.to_string(ltl::Syntax::Spin);
  std::string templ = (std::filesystem::temp_directory_path() / "rearm_spin_XXXXXX").string();
  std::vector<char> dir_buf(templ.begin(), templ.end());
  dir_buf.push_back('\0');
  if (::mkdtemp(dir_buf.data()) == nullptr) {
    run.diagnostics = "mkdtemp failed";
    return run;
  }
  const std::filesystem::path dir(dir_buf.data());
  const std::string out_path = (dir / "stdout.txt").string();
  const std::string err_path = (dir / "stderr.txt").string();

  // Everything the child needs is prepared before fork (only async-signal-safe calls after).
  const std::string bound = std::to_string(timeout_seconds) + "s";
  std::vector<std::string> args = {"timeout", "-k", kKillAfter, bound, "spin", "-f", formula};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string dir_str = dir.string();

  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir_str.c_str()) != 0) ::_exit(127);
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int in = ::open("/dev/null", O_RDONLY);
    if (out < 0 || err < 0 || in < 0) ::_exit(127);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execvp("timeout", argv.data());
    ::_exit(127);
  }
  if (pid < 0) {
    run.diagnostics = "fork failed";
  } else {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.never_claim = slurp(out_path);
    run.diagnostics = slurp(err_path);
    if (run.exit_code == kTimeoutExitCode || run.exit_code == 128 + 9) {
      run.status = SpinRun::Status::kTimeout;
    } else if (run.exit_code == 0 && run.never_claim.find("never") != std::string::npos) {
      run.status = SpinRun::Status::kOk;
    } else {
      run.status = SpinRun::Status::kFailed;
      if (run.diagnostics.empty()) run.diagnostics = run.never_claim;
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  return run;
}

std::vector<SpinRun> run_spin_all(const std::vector<ltl::Formula>& formulas, double timeout_seconds,
                                  unsigned threads) {
  if (threads == 0) threads = std::max(2u, std::thread::hardware_concurrency());
  std::vector<SpinRun> runs(formulas.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < formulas.size(); i = next++) {
      runs[i] = run_spin(formulas[i], timeout_seconds);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return runs;
}

std::optional<std::string> spin_never_claim(const ltl::Formula& f, double timeout_seconds) {
  SpinRun run = run_spin(f, timeout_seconds);
  if (run.status != SpinRun::Status::kOk) return std::nullopt;
  return std::move(run.never_claim);
}

}  // namespace rearm::test_support
