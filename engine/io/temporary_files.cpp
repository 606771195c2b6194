#include "engine/io/temporary_files.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <utility>

namespace tubemesh::io {

namespace {

// More than any run writes at once (one per output and the report).
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;

struct Slot {
    std::atomic<bool> taken{false};  // owned by a TrackedTemporary
    std::atomic<bool> live{false};   // path is complete and may be unlinked
    char path[kPathBytes];
};

std::array<Slot, kSlots> slots;
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler reads the slots' flags");

void unlink_all(int signal_number) {
    for (Slot& s : slots)
        if (s.live.load(std::memory_order_acquire)) ::unlink(s.path);
    // SA_RESETHAND restored the default action; it ends the process once the handler returns.
    ::raise(signal_number);
}

}  // namespace

TrackedTemporary::TrackedTemporary(const std::filesystem::path& path) {
    const std::string& text = path.native();
    if (text.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        bool expected = false;
        if (!slots[i].taken.compare_exchange_strong(expected, true)) continue;
        std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
        slots[i].live.store(true, std::memory_order_release);
        slot_ = i;
        return;
    }
}

TrackedTemporary::TrackedTemporary(TrackedTemporary&& other) noexcept : slot_(std::exchange(other.slot_, -1)) {}

TrackedTemporary& TrackedTemporary::operator=(TrackedTemporary&& other) noexcept {
    if (this != &other) {
        release();
        slot_ = std::exchange(other.slot_, -1);
    }
    return *this;
}

void TrackedTemporary::release() noexcept {
    if (slot_ < 0) return;
    slots[slot_].live.store(false, std::memory_order_release);
    slots[slot_].taken.store(false, std::memory_order_release);
    slot_ = -1;
}

void remove_temporaries_on_signals() {
    struct sigaction action {};
    action.sa_handler = unlink_all;
    constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
    sigemptyset(&action.sa_mask);
    for (int s : kSignals) sigaddset(&action.sa_mask, s);
    action.sa_flags = SA_RESETHAND;
    for (int s : kSignals) sigaction(s, &action, nullptr);
}

}  // namespace tubemesh::io
