#include "common/interrupt_cleanup.hpp"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>

namespace tri {
namespace {

// The one piece of global state of the output code: a signal handler can only reach what is
// global, and it may only read lock-free atomics and fixed buffers (no allocation, no locks).
struct Slot {
  enum State : int { free, writing, ready };
  std::atomic<int> state{free};
  std::atomic<unsigned long> order{0};  // registration order: folders are removed newest first
  LeftoverKind kind = LeftoverKind::file;
  std::array<char, PATH_MAX> path{};
};
constexpr std::size_t slot_count = 64;
std::array<Slot, slot_count> slots;
std::atomic<unsigned long> registrations{0};
static_assert(std::atomic<int>::is_always_lock_free &&
              std::atomic<unsigned long>::is_always_lock_free);

constexpr std::array<int, 5> cleaned_signals{SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXFSZ};

void remove_leftovers_and_die(int signal_number) {
  for (Slot& slot : slots) {
    if (slot.state.load() == Slot::ready && slot.kind == LeftoverKind::file) {
      ::unlink(slot.path.data());
    }
  }
  // Folders made for outputs, the deepest (registered last) first; rmdir keeps non-empty ones.
  for (unsigned long order = registrations.load(); order > 0; --order) {
    for (Slot& slot : slots) {
      if (slot.state.load() == Slot::ready && slot.kind == LeftoverKind::folder &&
          slot.order.load() == order) {
        ::rmdir(slot.path.data());
      }
    }
  }
  // The default action once the handler returns: the parent sees the signal that ended us.
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

// Checked at every registration, so a signal the program set back to its default is covered.
void install_handlers() {
  for (const int signal_number : cleaned_signals) {
    struct sigaction current {};
    if (::sigaction(signal_number, nullptr, &current) != 0) continue;
    // An ignored signal or a program's own handler stays as the program set it.
    if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = remove_leftovers_and_die;
    sigfillset(&action.sa_mask);  // no second signal interrupts the removal
    ::sigaction(signal_number, &action, nullptr);
  }
}

}  // namespace

InterruptCleanup::InterruptCleanup(const std::filesystem::path& path, LeftoverKind kind) {
  std::error_code error;
  const std::string absolute = std::filesystem::absolute(path, error).string();
  if (error || absolute.size() >= PATH_MAX) return;
  install_handlers();
  for (std::size_t i = 0; i < slot_count; ++i) {
    int expected = Slot::free;
    if (!slots[i].state.compare_exchange_strong(expected, Slot::writing)) continue;
    slots[i].kind = kind;
    std::memcpy(slots[i].path.data(), absolute.c_str(), absolute.size() + 1);
    slots[i].order.store(++registrations);
    slots[i].state.store(Slot::ready);
    slot_ = static_cast<int>(i);
    return;
  }
}

InterruptCleanup& InterruptCleanup::operator=(InterruptCleanup&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void InterruptCleanup::release() {
  if (slot_ < 0) return;
  slots[static_cast<std::size_t>(slot_)].state.store(Slot::free);
  slot_ = -1;
}

}  // namespace tri
