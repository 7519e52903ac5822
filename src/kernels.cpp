// kernels.cpp — the kernel tables (kernels.h): one per instruction set, and the choice of
// the default one, made once. The only file that compares instruction sets.
#include "kernels.h"

#include <cstdlib>

#include "lines/line_tabulated_internal.h"
#include "raster/fill/fill.h"
#include "raster/msaa/msaa_kernels.h"
#include "raster/setup/setup.h"
#include "raster/texture/texture_walk.h"
#include "simd_config.h"

namespace tiny3d::detail {

namespace {

// Entries a set does not have stay null (the portable reference runs). The SIMD tables
// exist in every build so that kernels_for never fails; kernels_run says which run.
constexpr kernel_table PORTABLE = {
    raster_simd::portable, "portable", line_simd::portable, nullptr, nullptr, fill_fast_bins_portable, nullptr,
    nullptr, false, false, nullptr, nullptr, nullptr, nullptr};
#ifdef TINY3D_SSE2
constexpr kernel_table SSE2 = {
    raster_simd::sse2, "sse2", line_simd::sse2, nullptr, nullptr, fill_fast_bins_sse2, nullptr,
    msaa_fill_sse2, false, true, nullptr, nullptr, nullptr, nullptr};
#else
constexpr kernel_table SSE2 = {raster_simd::sse2, "sse2", line_simd::portable, nullptr, nullptr,
                               fill_fast_bins_portable, nullptr, nullptr, false, false, nullptr, nullptr, nullptr,
                               nullptr};
#endif
#ifdef TINY3D_AVX2
constexpr kernel_table AVX2 = {
    raster_simd::avx2, "avx2", line_simd::sse2, setup_fast_batch_avx2, setup_msaa_batch_avx2, fill_fast_bins_avx2,
    nullptr, fill_function_avx2, true, true, resolve_blocks4_avx2, resolve_rows8_avx2, resolve_rows16_avx2,
    walk_taps_avx2};
#else
// (Its 4-sample tiles keep the block layout, as the AVX-512 table's below.)
constexpr kernel_table AVX2 = {raster_simd::avx2, "avx2", SSE2.lines, nullptr, nullptr, SSE2.fill_fast_bins,
                               nullptr, SSE2.msaa_fill, true, SSE2.resolve_rows_simd, nullptr, nullptr,
                               nullptr, nullptr};
#endif
#ifdef TINY3D_AVX512
constexpr kernel_table AVX512 = {
    raster_simd::avx512, "avx512", line_simd::avx512, setup_fast_batch_avx512, setup_msaa_batch_avx512,
    fill_fast_bins_avx512, fill_rows_narrow_avx512, fill_function_avx512, true, true, resolve_blocks4_avx512,
    AVX2.resolve_rows8, AVX2.resolve_rows16, AVX2.walk_taps};
#else
// (Its 4-sample tiles keep the block layout: a layout, which every kernel reads.)
constexpr kernel_table AVX512 = {raster_simd::avx512, "avx512", SSE2.lines, nullptr, nullptr, SSE2.fill_fast_bins,
                                 nullptr, SSE2.msaa_fill, true, SSE2.resolve_rows_simd, nullptr,
                                 AVX2.resolve_rows8, AVX2.resolve_rows16, AVX2.walk_taps};
#endif

constexpr line_kernels LINES_PORTABLE = {tabulated::draw_portable, nullptr, nullptr};
#ifdef TINY3D_SSE2
constexpr line_kernels LINES_SSE2 = {tabulated::draw_sse2, nullptr, nullptr};
#else
constexpr line_kernels LINES_SSE2 = LINES_PORTABLE;
#endif
#ifdef TINY3D_AVX512
constexpr line_kernels LINES_AVX512 = {LINES_SSE2.draw_one, tabulated::draw_batch_avx512, tabulated::prepare8_avx512};
#else
constexpr line_kernels LINES_AVX512 = LINES_SSE2;
#endif

bool cpu_runs(raster_simd simd) {
    switch (simd) {
        case raster_simd::portable: return true;
#ifdef TINY3D_SSE2  // the AVX2 and AVX-512 tables fall back on SSE2's kernels
        case raster_simd::sse2: return true;
#ifdef TINY3D_AVX2
        case raster_simd::avx2: return cpu_has_avx2();
#endif
#ifdef TINY3D_AVX512
        case raster_simd::avx512: return cpu_has_avx512();
#endif
#endif
        default: return false;
    }
}

struct default_choice {
    const kernel_table *table = &PORTABLE;
    kernel_request request;
};

const default_choice &chosen() {
    static const default_choice once = [] {
        default_choice c;
        for (raster_simd s : {raster_simd::avx512, raster_simd::avx2, raster_simd::sse2})
            if (cpu_runs(s)) {
                c.table = &kernels_for(s);
                break;
            }
        const char *env = std::getenv("TINY3D_KERNELS");
        c.request.requested = env ? env : "";
        for (raster_simd s : {raster_simd::portable, raster_simd::sse2, raster_simd::avx2, raster_simd::avx512})
            if (c.request.requested == kernels_for(s).name && cpu_runs(s)) {
                c.table = &kernels_for(s);
                c.request.honoured = true;
            }
        return c;
    }();
    return once;
}

}  // namespace

const kernel_table &kernels_for(raster_simd simd) {
    switch (simd) {
        case raster_simd::sse2: return SSE2;
        case raster_simd::avx2: return AVX2;
        case raster_simd::avx512: return AVX512;
        default: return PORTABLE;
    }
}

bool kernels_run(raster_simd simd) { return cpu_runs(simd); }
const kernel_table &default_kernels() { return *chosen().table; }
const kernel_request &default_kernels_request() { return chosen().request; }

const line_kernels &line_kernels_for(line_simd simd) {
    switch (simd) {
        case line_simd::sse2: return LINES_SSE2;
        case line_simd::avx512: return LINES_AVX512;
        default: return LINES_PORTABLE;
    }
}

bool line_kernels_run(line_simd simd) {
    switch (simd) {
        case line_simd::portable: return true;
        case line_simd::sse2: return cpu_runs(raster_simd::sse2);
        case line_simd::avx512: return cpu_runs(raster_simd::avx512);
        default: return false;
    }
}

}  // namespace tiny3d::detail

namespace tiny3d {

raster_simd best_raster_simd() { return detail::default_kernels().simd; }
line_simd best_line_simd() { return detail::default_kernels().lines; }
const char *raster_simd_name(raster_simd simd) { return detail::kernels_for(simd).name; }

raster_simd_choice default_raster_simd() {
    const detail::kernel_request &r = detail::default_kernels_request();
    return {detail::default_kernels().simd, r.requested, r.honoured};
}

}  // namespace tiny3d
