// pthread_once as the programs link it (framework/core/runtime/quiet_once.cpp): the routine
// runs exactly once and every caller returns after it finished, sleepers are woken, an
// exception lets the next caller run it, and a child forked while another thread runs the
// routine runs it itself. Each scenario runs in a child process under an alarm: a lost wake-up
// is a killed process, not a hung suite.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr unsigned kAlarmSeconds = 30;  // a scenario that has not ended by then hangs

// Runs `scenario` in a forked child under an alarm; true when it returned true in time.
bool in_child(const std::function<bool()>& scenario) {
  const pid_t pid = fork();
  if (pid == 0) {
    alarm(kAlarmSeconds);
    _exit(scenario() ? 0 : 1);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) != pid) return false;
  if (WIFSIGNALED(status)) {
    ADD_FAILURE() << "the scenario's process died of signal " << WTERMSIG(status)
                  << (WTERMSIG(status) == SIGALRM ? " (the alarm: a caller never returned)" : "");
    return false;
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void pause_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

// The routine of the plain scenario: slow, so that the other callers arrive and sleep.
pthread_once_t g_once = PTHREAD_ONCE_INIT;
std::atomic<int> g_runs{0};
std::atomic<bool> g_finished{false};
void slow_routine() {
  g_runs.fetch_add(1);
  pause_ms(100);
  g_finished.store(true);
}

TEST(QuietOnce, IsTheProgramsOwnPthreadOnce) {
  Dl_info info{};
  ASSERT_NE(dladdr(reinterpret_cast<void*>(&pthread_once), &info), 0);
  ASSERT_NE(info.dli_fname, nullptr);
  const std::string where = info.dli_fname;
#ifdef REARM_QUIET_ONCE
  EXPECT_EQ(where.find("libc.so"), std::string::npos) << "pthread_once resolves to " << where;
#else
  EXPECT_NE(where.find("libc.so"), std::string::npos) << "pthread_once resolves to " << where;
#endif
}

TEST(QuietOnce, RunsOnceAndEveryCallerSeesItFinished) {
  EXPECT_TRUE(in_child([] {
    constexpr int kThreads = 8;
    std::atomic<int> early{0};  // callers that returned before the routine finished
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&early, t] {
        pause_ms(5 * t);
        pthread_once(&g_once, slow_routine);
        if (!g_finished.load()) early.fetch_add(1);
      });
    }
    for (std::thread& th : threads) th.join();
    pthread_once(&g_once, slow_routine);  // done: returns at once
    return g_runs.load() == 1 && early.load() == 0;
  }));
}

TEST(QuietOnce, AnExceptionLetsTheNextCallerRunIt) {
  EXPECT_TRUE(in_child([] {
    std::once_flag flag;
    std::atomic<int> attempts{0};
    auto routine = [&attempts] {
      if (attempts.fetch_add(1) == 0) {
        pause_ms(100);  // the second caller arrives and sleeps meanwhile
        throw std::runtime_error("first attempt fails");
      }
    };
    bool thrown = false;
    std::thread first([&] {
      try {
        std::call_once(flag, routine);
      } catch (const std::runtime_error&) {
        thrown = true;
      }
    });
    pause_ms(30);
    std::call_once(flag, routine);  // sleeps, is woken by the failure, runs it
    first.join();
    std::call_once(flag, routine);  // done now
    return thrown && attempts.load() == 2;
  }));
}

// The fork scenario's routine blocks until released; the child runs its own.
pthread_once_t f_once = PTHREAD_ONCE_INIT;
std::atomic<bool> f_entered{false};
std::atomic<bool> f_release{false};
std::atomic<int> f_runs{0};
void blocking_routine() {
  f_runs.fetch_add(1);
  f_entered.store(true);
  while (!f_release.load()) pause_ms(1);
}
void child_routine() { f_runs.fetch_add(100); }

TEST(QuietOnce, AForkedChildRunsTheRoutineOfADeadInitializer) {
  EXPECT_TRUE(in_child([] {
    std::thread holder([] { pthread_once(&f_once, blocking_routine); });
    while (!f_entered.load()) pause_ms(1);
    const bool child_ok = in_child([] {
      pthread_once(&f_once, child_routine);  // the holder does not exist here
      pthread_once(&f_once, child_routine);
      return f_runs.load() == 101;
    });
    f_release.store(true);
    holder.join();
    pthread_once(&f_once, child_routine);
    return child_ok && f_runs.load() == 1;
  }));
}

}  // namespace
