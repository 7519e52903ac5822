// tests/alloc_tracker.h — replaces the global operator new / delete (all forms, aligned
// included) to count allocations and remember the largest single request, and can fail
// the N-th allocation on purpose. Include it in
// exactly ONE translation unit of a test program (each tests/*_test.cpp is one program).
// Single-threaded use: counters are plain atomics read between calls, never reset by
// another thread. Memory comes from malloc / aligned_alloc, so ASan still sees every block
// and reports leaks.
#ifndef TINY3D_ALLOC_TRACKER_H
#define TINY3D_ALLOC_TRACKER_H

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace alloc_tracker {

struct counters {
    std::atomic<std::size_t> allocations{0};
    std::atomic<std::size_t> largest{0};  // bytes of the largest single request
};

inline counters &stats() {
    static counters c;
    return c;
}

// Failing on purpose (tests/alloc_failure_test.cpp): the allocation, counted from 1 since
// fail_allocation(n), that returns null (operator new then throws std::bad_alloc); 0: none.
inline std::atomic<std::size_t> &failing_allocation() {
    static std::atomic<std::size_t> n{0};
    return n;
}
inline void fail_allocation(std::size_t n) {
    stats().allocations.store(0);
    failing_allocation().store(n);
}

// Counts an allocation; returns its number.
inline std::size_t note(std::size_t bytes) {
    counters &c = stats();
    const std::size_t number = c.allocations.fetch_add(1, std::memory_order_relaxed) + 1;
    std::size_t prev = c.largest.load(std::memory_order_relaxed);
    while (bytes > prev && !c.largest.compare_exchange_weak(prev, bytes, std::memory_order_relaxed)) {
    }
    return number;
}

inline std::size_t allocations() { return stats().allocations.load(); }
inline std::size_t largest() { return stats().largest.load(); }
inline void reset_largest() { stats().largest.store(0); }

// The largest single allocation made while fn runs.
template <class Fn>
std::size_t largest_allocation_during(Fn &&fn) {
    reset_largest();
    fn();
    return largest();
}

inline void *allocate(std::size_t bytes, std::size_t align) {
    if (note(bytes) == failing_allocation().load(std::memory_order_relaxed)) return nullptr;
    if (bytes == 0) bytes = 1;
    if (align <= alignof(std::max_align_t)) return std::malloc(bytes);
    const std::size_t rounded = (bytes + align - 1) / align * align;  // aligned_alloc needs a multiple
    return std::aligned_alloc(align, rounded);
}

// Out of line on purpose: g++ would otherwise see `free` inlined into operator delete
// and warn (-Wmismatched-new-delete) that it frees what operator new returned.
[[gnu::noinline]] inline void release(void *p) noexcept { std::free(p); }

}  // namespace alloc_tracker

// ---- the replaced operators (definitions: this header goes into one TU only) -----------
void *operator new(std::size_t n) {
    if (void *p = alloc_tracker::allocate(n, 0)) return p;
    throw std::bad_alloc();
}
void *operator new[](std::size_t n) { return operator new(n); }
void *operator new(std::size_t n, const std::nothrow_t &) noexcept { return alloc_tracker::allocate(n, 0); }
void *operator new[](std::size_t n, const std::nothrow_t &) noexcept { return alloc_tracker::allocate(n, 0); }
void *operator new(std::size_t n, std::align_val_t a) {
    if (void *p = alloc_tracker::allocate(n, std::size_t(a))) return p;
    throw std::bad_alloc();
}
void *operator new[](std::size_t n, std::align_val_t a) { return operator new(n, a); }
void *operator new(std::size_t n, std::align_val_t a, const std::nothrow_t &) noexcept {
    return alloc_tracker::allocate(n, std::size_t(a));
}
void *operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t &) noexcept {
    return alloc_tracker::allocate(n, std::size_t(a));
}
void operator delete(void *p) noexcept { alloc_tracker::release(p); }
void operator delete[](void *p) noexcept { alloc_tracker::release(p); }
void operator delete(void *p, std::size_t) noexcept { alloc_tracker::release(p); }
void operator delete[](void *p, std::size_t) noexcept { alloc_tracker::release(p); }
void operator delete(void *p, const std::nothrow_t &) noexcept { alloc_tracker::release(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { alloc_tracker::release(p); }
void operator delete(void *p, std::align_val_t) noexcept { alloc_tracker::release(p); }
void operator delete[](void *p, std::align_val_t) noexcept { alloc_tracker::release(p); }
void operator delete(void *p, std::size_t, std::align_val_t) noexcept { alloc_tracker::release(p); }
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept { alloc_tracker::release(p); }
void operator delete(void *p, std::align_val_t, const std::nothrow_t &) noexcept { alloc_tracker::release(p); }
void operator delete[](void *p, std::align_val_t, const std::nothrow_t &) noexcept { alloc_tracker::release(p); }

#endif
