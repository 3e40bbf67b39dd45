// pthread_once without a system call when no thread waits (docs/architecture.md, "Process-wide
// runtime"). Linked into rearm's programs, benchmarks and tests (CMake option
// REARM_QUIET_ONCE), never into the libraries: a program's own definition of pthread_once takes
// the place of glibc's for the program and every shared library it loads (std::call_once, TBB).
//
// Why: CGAL's exact kernel (Epeck) under threads evaluates each lazy number or point exactly
// through std::call_once, that is pthread_once, on its first exact use; glibc 2.36 ends every
// first call of a pthread_once with a futex wake system call, waiter or not. On a virtual
// machine a system call costs microseconds: the wakes were about a third of a cold topology
// check while carrying and of an uncached mapped-space build. Here a flag records whether some
// thread waits, and the initializer wakes only then.
//
// The once word (an int, PTHREAD_ONCE_INIT = 0): bit 0 an initializer runs, bit 1 done, bit 2
// some thread sleeps on the word, bits 3 and up the fork generation of the running
// initializer. After fork() only the forking thread survives: an initializer of an earlier
// generation is dead, and the child's first caller runs the routine itself (POSIX leaves this
// undefined; glibc does the same). An exception out of the routine (a C++ exception through
// std::call_once, or a thread's cancellation) resets the word and wakes the sleepers, one of
// whom runs the routine next, as std::call_once requires.
#include <linux/futex.h>
#include <pthread.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <climits>

namespace {

constexpr int kRunning = 1;
constexpr int kDone = 2;
constexpr int kWaiters = 4;
constexpr int kGenerationStep = 8;
constexpr int kGenerationMask = ~(kGenerationStep - 1);

std::atomic<int> generation{0};  // advanced in each forked child

void advance_generation() { generation.fetch_add(kGenerationStep, std::memory_order_relaxed); }

// Registered before main (and before any fork of the program's own).
[[gnu::constructor]] void register_fork_handler() {
  pthread_atfork(nullptr, nullptr, advance_generation);
}

std::atomic<int>& word(pthread_once_t* control) {
  static_assert(sizeof(pthread_once_t) == sizeof(std::atomic<int>));
  return *reinterpret_cast<std::atomic<int>*>(control);
}

void wake_all(std::atomic<int>& w) {
  syscall(SYS_futex, reinterpret_cast<int*>(&w), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
}

void sleep_while(std::atomic<int>& w, int value) {
  syscall(SYS_futex, reinterpret_cast<int*>(&w), FUTEX_WAIT_PRIVATE, value, nullptr, nullptr, 0);
}

// Runs the routine as the word's initializer; the word was set to `mine` by this thread.
void run(std::atomic<int>& w, void (*init)()) {
  try {
    init();
  } catch (...) {
    if (w.exchange(0, std::memory_order_acq_rel) & kWaiters) wake_all(w);
    throw;
  }
  if (w.exchange(kDone, std::memory_order_acq_rel) & kWaiters) wake_all(w);
}

}  // namespace

extern "C" int pthread_once(pthread_once_t* control, void (*init)()) {
  std::atomic<int>& w = word(control);
  int v = w.load(std::memory_order_acquire);
  while (!(v & kDone)) {
    const int mine = generation.load(std::memory_order_relaxed) | kRunning;
    const bool live = (v & kRunning) && (v & kGenerationMask) == (mine & kGenerationMask);
    if (!live) {  // free, or left by an initializer that did not survive a fork
      if (w.compare_exchange_weak(v, mine, std::memory_order_acquire)) {
        run(w, init);
        return 0;
      }
      continue;  // v reloaded
    }
    if (!(v & kWaiters) && !w.compare_exchange_weak(v, v | kWaiters, std::memory_order_acquire)) {
      continue;
    }
    sleep_while(w, v | kWaiters);  // returns at once if the word changed meanwhile
    v = w.load(std::memory_order_acquire);
  }
  return 0;
}
