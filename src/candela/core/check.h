#pragma once
// Internal invariants. A failed check is a bug in candela, never bad user input (that is a
// SceneError): it prints the condition and location and aborts.
#include <cstdio>
#include <cstdlib>

namespace candela::detail {
[[noreturn]] inline void check_failed(const char* cond, const char* file, int line) {
    std::fprintf(stderr, "candela: internal error: check failed: %s at %s:%d\n", cond, file, line);
    std::abort();
}
}  // namespace candela::detail

// Always on, also in Release: for cheap checks whose failure would otherwise corrupt an image.
#define CANDELA_CHECK(cond) \
    ((cond) ? (void)0 : ::candela::detail::check_failed(#cond, __FILE__, __LINE__))

// Debug builds only: for checks on hot paths.
#ifdef NDEBUG
#define CANDELA_DCHECK(cond) ((void)0)
#else
#define CANDELA_DCHECK(cond) CANDELA_CHECK(cond)
#endif
