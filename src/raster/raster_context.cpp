// raster_context.cpp — the render context: worker pool, vertex transform and shading,
// culling, clipping, binning into horizontal bands, band-parallel rasterization, the
// translucent queue. Every buffer is owned here and reused from frame to frame.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <thread>

#include "raster_internal.h"
#include "uv_derivatives.h"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace tiny3d {

namespace {

constexpr int MAX_THREADS = 16;
constexpr std::size_t CACHE_LINE = 64;  // bytes
// The frame is cut into horizontal bands of BAND_ROWS rows (at most MAX_BANDS), so that one
// band's colour and depth rows stay in cache while all its triangles are drawn; thread t
// draws bands t, t + n, t + 2n, …
constexpr int BAND_ROWS = 32;
constexpr int MAX_BANDS = 128;
// Blocks of neighbouring bands per thread: 2 (256-row blocks at 1024 px on two threads) lets
// a thread skip whole cluster chunks (~100 rows high at Scene S level 6) far more often than
// 4 did, and fewer triangles straddle two owners; per-thread work stayed as even on Scene S
// and on the sphere moved off-centre (documentation/raster.md).
constexpr int BLOCKS_PER_THREAD = 2;
static_assert(MAX_BANDS <= 256, "row_band stores band numbers in 8 bits");
// Guard band: the x/y clip planes sit at |x|, |y| ≤ guard·w, chosen so that the whole band
// spans fewer pixels than the 32-bit fill allows; never tighter than the frustum itself.
constexpr float GUARD_SPAN_PIXELS = 2000.0f;
constexpr float MAX_GUARD = 4.0f;

// Waits until done() holds by spinning (with a pause hint) for at most SPIN_LIMIT; returns
// whether it did. Phases of a frame follow each other within microseconds, far less than a
// sleep/wake-up through the kernel costs, so the pool spins first and sleeps only after.
constexpr std::chrono::microseconds SPIN_LIMIT{50};
constexpr int SPINS_PER_CLOCK_READ = 64;

template <class Done>
bool spin_until(Done &&done) {
    const auto give_up = std::chrono::steady_clock::now() + SPIN_LIMIT;
    for (;;) {
        for (int k = 0; k < SPINS_PER_CLOCK_READ; ++k) {
            if (done()) return true;
#ifdef __SSE2__
            _mm_pause();
#endif
        }
        if (std::chrono::steady_clock::now() > give_up) return false;
    }
}

// Waits until done() holds: spins with a pause hint, yielding the core every
// SPINS_PER_CLOCK_READ spins (the thread waited for may be waiting for this core).
template <class Done>
void spin_until_yielding(Done &&done) {
    for (;;) {
        for (int k = 0; k < SPINS_PER_CLOCK_READ; ++k) {
            if (done()) return;
#ifdef __SSE2__
            _mm_pause();
#endif
        }
        std::this_thread::yield();
    }
}

// A fixed set of worker threads; run(job) calls job(i) for i = 0..n−1, i = 0 on the caller,
// and returns when all are done. No allocation per run. A new job is announced by bumping
// `generation_` (the job pointer is published by that release store); workers and the
// caller spin briefly on the atomics, then sleep on the condition variables. Every state
// change is followed by locking and unlocking the mutex before notifying, so a thread that
// checked the state under the mutex just before the change is already waiting: no lost
// wake-up.
class worker_pool {
public:
    explicit worker_pool(int threads) {
        for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { loop(i); });
    }
    ~worker_pool() {
        stop_.store(true);
        generation_.fetch_add(1);
        notify(wake_, true);
        for (std::thread &t : workers_) t.join();
    }
    int size() const { return static_cast<int>(workers_.size()) + 1; }

    template <class Job>
    void run(Job &job) {
        if (workers_.empty()) {
            job(0);
            return;
        }
        call_ = [](void *j, int i) { (*static_cast<Job *>(j))(i); };
        job_ = &job;
        pending_.store(static_cast<int>(workers_.size()));
        generation_.fetch_add(1);
        notify(wake_, true);
        job(0);
        auto finished = [this] { return pending_.load() == 0; };
        if (spin_until(finished)) return;
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, finished);
    }

private:
    void notify(std::condition_variable &cv, bool all) {
        { std::lock_guard<std::mutex> lock(mutex_); }
        if (all) cv.notify_all();
        else cv.notify_one();
    }

    void loop(int index) {
        unsigned long long seen = 0;
        for (;;) {
            auto announced = [&] { return generation_.load() != seen; };
            if (!spin_until(announced)) {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, announced);
            }
            if (stop_.load()) return;
            seen = generation_.load();
            call_(job_, index);
            if (pending_.fetch_sub(1) == 1) notify(done_, false);
        }
    }

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    void (*call_)(void *, int) = nullptr;
    void *job_ = nullptr;
    std::atomic<unsigned long long> generation_{0};
    std::atomic<int> pending_{0};
    std::atomic<bool> stop_{false};
};

// A transformed vertex: what the triangle walk reads, 20 bytes (the clip-space position,
// which only clipping needs, is kept in an array of its own, so that the walk's vertex
// reads and the transform's writes are 2.6× smaller).
struct xvertex {
    std::int32_t snapped_x, snapped_y;  // screen position in 1/16 px, valid when `snapped`
    float depth;                        // window depth 0.5·z/w + 0.5, valid when outcode has no CLIP_NEAR bit
    float shade;                        // Gouraud intensity (or 0)
    std::uint8_t outcode;
    bool snapped;                       // screen position usable (snap_vertex succeeded)
};

// Per-vertex attributes of the generic (per-pixel) path, in clip_vertex::attr order.
enum attr_slot { ATTR_PX, ATTR_PY, ATTR_PZ, ATTR_NX, ATTR_NY, ATTR_NZ, ATTR_U, ATTR_V, ATTR_SHADE, ATTR_COUNT };
static_assert(ATTR_COUNT <= CLIP_MAX_ATTRIBUTES);

// A triangle for the per-pixel path (Phong, textures, translucency).
struct generic_triangle {
    screen_vertex v[3];
    float attr[3][ATTR_COUNT];
    float mean_depth;
    std::uint32_t state;     // index into the frame's draw states
    std::uint32_t sequence;  // submission order among the translucent ones (sort tie-break)
};

struct draw_state {
    draw_params params;
};

// The per-draw constants of the vertex transform.
struct vertex_job {
    mat4_t mvp;
    normal_transform nt;
    float half_w, half_h;
    bool gouraud, generic;
    bool directional_gouraud;  // Gouraud with directional lights only: the SSE2 shading path
};

// What a thread does with one cluster chunk of the draw: skip it, or walk it (and whether it
// counts the chunk's culled triangles).
struct chunk_walk {
    bool walk, counts;
};

// The vertices one transform() call handles: 0..count−1, or list[0..count).
struct vertex_set {
    const std::uint32_t *list;
    std::size_t count;
    std::uint32_t operator[](std::size_t k) const { return list ? list[k] : static_cast<std::uint32_t>(k); }
};

screen_vertex to_screen(vec4_t c, float half_w, float half_h) {
    const float inv_w = 1.0f / c.w;
    return {(c.x * inv_w + 1.0f) * half_w, (1.0f - c.y * inv_w) * half_h, 0.5f * c.z * inv_w + 0.5f, inv_w};
}

vec4_t mul(const mat4_t &m, vec3_t p) {
    return {m.m[0] * p.x + m.m[4] * p.y + m.m[8] * p.z + m.m[12], m.m[1] * p.x + m.m[5] * p.y + m.m[9] * p.z + m.m[13],
            m.m[2] * p.x + m.m[6] * p.y + m.m[10] * p.z + m.m[14], m.m[3] * p.x + m.m[7] * p.y + m.m[11] * p.z + m.m[15]};
}

vec3_t mul3(const mat4_t &m, vec3_t p) {
    const vec4_t r = mul(m, p);
    return {r.x, r.y, r.z};
}

// Sphere (object space) entirely outside one frustum plane of clip = M·p? Planes from the
// rows of M (Gribb–Hartmann): row3 ± row_k, normalised.
bool sphere_outside(const mat4_t &m, vec3_t c, float radius) {
    auto row = [&](int r) { return vec4_t{m.m[r], m.m[4 + r], m.m[8 + r], m.m[12 + r]}; };
    const vec4_t w = row(3);
    for (int k = 0; k < 3; ++k) {
        const vec4_t rk = row(k);
        for (float sign : {1.0f, -1.0f}) {
            const vec4_t p{w.x + sign * rk.x, w.y + sign * rk.y, w.z + sign * rk.z, w.w + sign * rk.w};
            const float len = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
            if (!(len > 0.0f)) continue;
            if ((p.x * c.x + p.y * c.y + p.z * c.z + p.w) / len < -radius) return true;
        }
    }
    return false;
}

// Whether every vertex index of `triangles` is < count. Runs on the caller's thread before the
// workers start, so it is branch-free: no early exit, four indices per SSE2 compare.
bool indices_below(const std::vector<std::array<std::uint32_t, 3>> &triangles, std::size_t count) {
    if (count > std::numeric_limits<std::uint32_t>::max()) return true;
    const std::uint32_t *index = triangles.empty() ? nullptr : triangles.front().data();
    const std::size_t n = triangles.size() * 3;
    const std::uint32_t limit = static_cast<std::uint32_t>(count);
    std::size_t k = 0;
    std::uint32_t out_of_range = 0;
#ifdef __SSE2__
    // Unsigned index ≥ limit  ⇔  (index ^ 2³¹) > (limit − 1) ^ 2³¹ as signed (limit ≥ 1).
    if (limit > 0) {
        const __m128i flip = _mm_set1_epi32(static_cast<int>(0x80000000u));
        const __m128i last = _mm_xor_si128(_mm_set1_epi32(static_cast<int>(limit - 1)), flip);
        __m128i any = _mm_setzero_si128();
        for (; k + 4 <= n; k += 4) {
            const __m128i v = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i *>(index + k)), flip);
            any = _mm_or_si128(any, _mm_cmpgt_epi32(v, last));
        }
        out_of_range = static_cast<std::uint32_t>(_mm_movemask_epi8(any));
    }
#endif
    for (; k < n; ++k) out_of_range |= index[k] >= limit;
    return out_of_range == 0;
}

bool directional_only(const light_rig &rig) {
    for (int k = 0; k < rig.count; ++k)
        if (rig.lights[k].kind != light_kind::directional) return false;
    return true;
}

#ifdef __SSE2__
// unit_or_zero (lighting.h) of four vectors in SoA form, lane by lane with the same float
// operations, hence the same bits: v·(1/√|v|²), or 0 when |v|² ≤ 1e-30 or not finite.
inline void unit_or_zero_x4(__m128 &x, __m128 &y, __m128 &z) {
    const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
    constexpr float MIN_LENGTH_SQUARED = 1e-30f;  // as lighting_detail::unit_or_zero
    const __m128 usable = _mm_and_ps(_mm_cmpgt_ps(len2, _mm_set1_ps(MIN_LENGTH_SQUARED)),
                                     _mm_cmplt_ps(len2, _mm_set1_ps(std::numeric_limits<float>::infinity())));
    const __m128 scale = _mm_and_ps(usable, _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(len2)));
    x = _mm_and_ps(usable, _mm_mul_ps(x, scale));
    y = _mm_and_ps(usable, _mm_mul_ps(y, scale));
    z = _mm_and_ps(usable, _mm_mul_ps(z, scale));
}

// The position part of transform() for four vertices: clip = M·p, outcode, screen position
// and snap, lane by lane with the scalar code's float operations in the same order (mul,
// clip_outcode, to_screen, detail::snap_vertex), so every field gets the same bits.
// Vertices index[0..3] of `positions`, written to the same indices of out and out_clip.
void project_x4(const mat4_t &m, const vec3_t *positions, const std::uint32_t index[4], float guard, float half_w,
                float half_h, xvertex *out, vec4_t *out_clip) {
    const vec3_t &p0 = positions[index[0]], &p1 = positions[index[1]], &p2 = positions[index[2]], &p3 = positions[index[3]];
    const __m128 px = _mm_setr_ps(p0.x, p1.x, p2.x, p3.x);
    const __m128 py = _mm_setr_ps(p0.y, p1.y, p2.y, p3.y);
    const __m128 pz = _mm_setr_ps(p0.z, p1.z, p2.z, p3.z);
    auto row = [&](int r) {  // m[r]·x + m[4+r]·y + m[8+r]·z + m[12+r]
        return _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(m.m[r]), px), _mm_mul_ps(_mm_set1_ps(m.m[4 + r]), py)),
                                     _mm_mul_ps(_mm_set1_ps(m.m[8 + r]), pz)),
                          _mm_set1_ps(m.m[12 + r]));
    };
    __m128 x = row(0), y = row(1), z = row(2), w = row(3);
    // Outcode: a plane's bit is set unless its distance is ≥ 0 (NaN is outside).
    const __m128 zero = _mm_setzero_ps(), gw = _mm_mul_ps(_mm_set1_ps(guard), w);
    const __m128 distance[6] = {_mm_add_ps(z, w), _mm_sub_ps(w, z), _mm_add_ps(x, gw),
                                _mm_sub_ps(gw, x), _mm_add_ps(y, gw), _mm_sub_ps(gw, y)};
    static_assert(CLIP_NEAR == 1 && CLIP_FAR == 2 && CLIP_LEFT == 4 && CLIP_RIGHT == 8 && CLIP_BOTTOM == 16 &&
                  CLIP_TOP == 32);
    __m128i code = _mm_setzero_si128();
    for (int k = 0; k < 6; ++k)
        code = _mm_or_si128(code, _mm_andnot_si128(_mm_castps_si128(_mm_cmpge_ps(distance[k], zero)), _mm_set1_epi32(1 << k)));
    alignas(16) std::uint32_t outcode[4];
    _mm_store_si128(reinterpret_cast<__m128i *>(outcode), code);
    // to_screen, computed for every lane (used only where w > 0, i.e. outside no near plane).
    const __m128 inv_w = _mm_div_ps(_mm_set1_ps(1.0f), w);
    const __m128 one = _mm_set1_ps(1.0f), half = _mm_set1_ps(0.5f);
    __m128 sx = _mm_mul_ps(_mm_add_ps(_mm_mul_ps(x, inv_w), one), _mm_set1_ps(half_w));
    __m128 sy = _mm_mul_ps(_mm_sub_ps(one, _mm_mul_ps(y, inv_w)), _mm_set1_ps(half_h));
    alignas(16) float depth[4];
    _mm_store_ps(depth, _mm_add_ps(_mm_mul_ps(_mm_mul_ps(half, z), inv_w), half));
    // snap_vertex: usable when |x|, |y| ≤ RASTER_MAX_COORD (false for NaN and ±∞ too).
    const __m128 abs_mask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)), limit = _mm_set1_ps(RASTER_MAX_COORD);
    const int usable = _mm_movemask_ps(_mm_and_ps(_mm_cmple_ps(_mm_and_ps(sx, abs_mask), limit),
                                                  _mm_cmple_ps(_mm_and_ps(sy, abs_mask), limit)));
    const __m128 sub = _mm_set1_ps(static_cast<float>(RASTER_SUBPIXEL_ONE));
    alignas(16) std::int32_t snap_x[4], snap_y[4];
    _mm_store_si128(reinterpret_cast<__m128i *>(snap_x), _mm_cvtps_epi32(_mm_mul_ps(sx, sub)));
    _mm_store_si128(reinterpret_cast<__m128i *>(snap_y), _mm_cvtps_epi32(_mm_mul_ps(sy, sub)));
    _MM_TRANSPOSE4_PS(x, y, z, w);
    const __m128 clip[4] = {x, y, z, w};
    for (int l = 0; l < 4; ++l) {
        xvertex &v = out[index[l]];
        alignas(16) float c[4];
        _mm_store_ps(c, clip[l]);
        out_clip[index[l]] = {c[0], c[1], c[2], c[3]};
        v.outcode = static_cast<std::uint8_t>(outcode[l]);
        v.depth = depth[l];
        v.snapped = !(v.outcode & CLIP_NEAR) && ((usable >> l) & 1);
        v.snapped_x = snap_x[l];
        v.snapped_y = snap_y[l];
    }
}

// shade_gouraud_vertex(rig, ·, apply_normal_transform(nt, normals[l])) for l = 0..3 with
// directional lights only (no position needed): the scalar code's operations in the same
// order on four lanes, so each result has the same bits as the scalar one.
void shade_gouraud_x4(const light_rig &rig, const normal_transform &nt, const vec3_t *normals, const std::uint32_t index[4],
                      float out[4]) {
    const vec3_t &n0 = normals[index[0]], &n1 = normals[index[1]], &n2 = normals[index[2]], &n3 = normals[index[3]];
    const __m128 nx = _mm_setr_ps(n0.x, n1.x, n2.x, n3.x);
    const __m128 ny = _mm_setr_ps(n0.y, n1.y, n2.y, n3.y);
    const __m128 nz = _mm_setr_ps(n0.z, n1.z, n2.z, n3.z);
    auto row = [&](int r) {  // nt.m[3r]·n.x + nt.m[3r+1]·n.y + nt.m[3r+2]·n.z
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(nt.m[3 * r]), nx), _mm_mul_ps(_mm_set1_ps(nt.m[3 * r + 1]), ny)),
                          _mm_mul_ps(_mm_set1_ps(nt.m[3 * r + 2]), nz));
    };
    __m128 x = row(0), y = row(1), z = row(2);
    unit_or_zero_x4(x, y, z);  // apply_normal_transform
    unit_or_zero_x4(x, y, z);  // shade_gouraud_vertex → shade_point's unit normal
    __m128 sum = _mm_set1_ps(rig.ambient);
    for (int k = 0; k < rig.count; ++k) {
        const light_t &l = rig.lights[k];
        const __m128 cosine = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, _mm_set1_ps(l.direction.x)), _mm_mul_ps(y, _mm_set1_ps(l.direction.y))),
                                         _mm_mul_ps(z, _mm_set1_ps(l.direction.z)));
        const __m128 lit = _mm_cmpgt_ps(cosine, _mm_setzero_ps());
        sum = _mm_add_ps(sum, _mm_and_ps(lit, _mm_mul_ps(_mm_set1_ps(l.intensity), cosine)));
    }
    // clamp01 (NaN → 0: maxps returns its second operand when one is NaN).
    _mm_store_ps(out, _mm_min_ps(_mm_max_ps(sum, _mm_setzero_ps()), _mm_set1_ps(1.0f)));
}
#endif

}  // namespace

struct render_context::impl {
    explicit impl(int threads) : pool(threads) {}

    worker_pool pool;
    canvas_t *target = nullptr;
    zbuffer depth;
    bool pending_clear = false;
    float clear_intensity = 0.0f;
    float guard = 1.0f;
    frame_stats stats;

    // What one phase-1 worker produced. Aligned to a cache line of its own: the vector
    // headers and stats are written per triangle, and two threads writing one line
    // (false sharing) made the two-thread setup slower than one thread's.
    struct alignas(CACHE_LINE) segment {
        std::vector<xvertex> vertices;   // every vertex of the draw, transformed by this thread
        std::vector<vec4_t> clip;        // their clip-space positions
        std::vector<float> vertex_attr;  // ATTR_COUNT per vertex (generic path only)
        std::vector<detail::fast_triangle> fast;
        std::vector<triangle_edges> wide;
        std::vector<generic_triangle> generic;
        std::vector<std::uint32_t> bins[MAX_BANDS];  // fast-triangle indices per band
        std::vector<chunk_walk> chunks;              // this draw's cluster chunks, as decided
        frame_stats stats;
    };
    segment segments[MAX_THREADS];
    std::vector<draw_state> states;              // this frame's draw calls
    std::vector<generic_triangle> translucent;   // queued for end_frame

    int band_count = 1;  // set per frame
    std::vector<std::uint8_t> row_band;  // the band holding each row (inverse of band_y0)
    std::uint8_t band_owner[MAX_BANDS];  // the thread that sets up each band's triangles
    // Per draw (numbered by draw_serial): which bands have been claimed for drawing, and which
    // segments are fully set up. A band is drawn by its owner or, once the owner's segment is
    // set up, by a thread that has finished its own bands (always from the owner's segment,
    // in submission order, so the pixels do not depend on who draws it).
    std::uint32_t draw_serial = 0;
    std::atomic<std::uint32_t> band_claim[MAX_BANDS] = {};
    struct alignas(CACHE_LINE) ready_flag {
        std::atomic<std::uint32_t> serial{0};
    };
    ready_flag segment_ready[MAX_THREADS];
    bool claim_band(int b) { return band_claim[b].exchange(draw_serial, std::memory_order_relaxed) != draw_serial; }
    int bands() const { return band_count; }
    int band_of(int y) const { return row_band[static_cast<std::size_t>(y)]; }
    // Whether thread t draws a band among rows [y0, y1] (inclusive, inside the target).
    bool draws_rows(int t, int y0, int y1) const {
        for (int b = band_of(y0); b <= band_of(y1); ++b)
            if (band_owner[b] == t) return true;
        return false;
    }
    int band_y0(int b) const { return static_cast<int>(static_cast<long long>(target->height) * b / bands()); }

    void clear_band(int b) {
        const int y0 = band_y0(b), y1 = band_y0(b + 1);
        if (y0 >= y1) return;
        detail::fill_floats(target->pixels[y0], static_cast<std::size_t>(y1 - y0) * target->width, clear_intensity);
        depth.clear_rows(y0, y1, 1.0f);
    }

    vertex_job make_vertex_job(const draw_params &p, const mat4_t &mvp, bool generic) const;
    void transform(const raster_mesh &m, const draw_params &p, const vertex_job &job, vertex_set set, segment &out);
    void setup(const raster_mesh &m, const draw_params &p, const vertex_job &job, std::uint32_t state, int thread,
               const detail::cluster_view *clusters, segment &out);
    void setup_range(const raster_mesh &m, const draw_params &p, std::uint32_t state, bool generic, int thread,
                     bool counts_all, std::size_t first, std::size_t last, segment &out);
    // Appends a fast triangle and its band bins (skips empty ones).
    void add_fast(const triangle_edges &t, const float depth[3], const float shade[3], segment &out) {
        detail::fast_triangle f;
        if (!detail::make_fast_triangle(t, depth, shade, static_cast<std::int32_t>(out.wide.size()), f)) return;
        if (f.wide >= 0) out.wide.push_back(t);
        bin_fast(f, out);
    }
    // Appends a set-up fast triangle and its band bins.
    void bin_fast(const detail::fast_triangle &f, segment &out) {
        const std::uint32_t index = static_cast<std::uint32_t>(out.fast.size());
        out.fast.push_back(f);
        for (int b = band_of(f.min_y); b <= band_of(f.max_y); ++b) out.bins[b].push_back(index);
    }
    void emit(const clip_vertex *poly, int n, const draw_params &p, std::uint32_t state, bool generic, bool count,
              segment &out);
    void draw_generic(const generic_triangle &g, int y0, int y1);
};

// ---- phase 1a: vertices -------------------------------------------------------------------

vertex_job render_context::impl::make_vertex_job(const draw_params &p, const mat4_t &mvp, bool generic) const {
    vertex_job job;
    job.mvp = mvp;
    job.nt = make_normal_transform(p.model);
    job.half_w = 0.5f * static_cast<float>(target->width);
    job.half_h = 0.5f * static_cast<float>(target->height);
    job.gouraud = p.shade == shading::gouraud;
    job.generic = generic;
    job.directional_gouraud = job.gouraud && !generic && directional_only(p.lights);
    return job;
}

void render_context::impl::transform(const raster_mesh &m, const draw_params &p, const vertex_job &job,
                                     vertex_set set, segment &out) {
    std::vector<xvertex> &vertices = out.vertices;
    std::vector<vec4_t> &clip = out.clip;
    std::vector<float> &vertex_attr = out.vertex_attr;
    std::size_t first = 0;
#ifdef __SSE2__
    for (; first + 4 <= set.count; first += 4) {
        const std::uint32_t index[4] = {set[first], set[first + 1], set[first + 2], set[first + 3]};
        project_x4(job.mvp, m.positions.data(), index, guard, job.half_w, job.half_h, vertices.data(), clip.data());
    }
#endif
    for (std::size_t k = first; k < set.count; ++k) {
        const std::uint32_t i = set[k];
        xvertex &x = vertices[i];
        clip[i] = mul(job.mvp, m.positions[i]);
        x.outcode = static_cast<std::uint8_t>(clip_outcode(clip[i], guard));
        x.snapped = false;
        if (!(x.outcode & CLIP_NEAR)) {
            const screen_vertex screen = to_screen(clip[i], job.half_w, job.half_h);
            x.depth = screen.z;
            x.snapped = detail::snap_vertex(screen, x.snapped_x, x.snapped_y);
        }
    }
#ifdef __SSE2__
    if (job.directional_gouraud) {
        std::size_t k = 0;
        for (; k + 4 <= set.count; k += 4) {
            const std::uint32_t index[4] = {set[k], set[k + 1], set[k + 2], set[k + 3]};
            alignas(16) float shade[4];
            shade_gouraud_x4(p.lights, job.nt, m.normals.data(), index, shade);
            for (int l = 0; l < 4; ++l) vertices[index[l]].shade = shade[l];
        }
        for (; k < set.count; ++k)
            vertices[set[k]].shade = shade_gouraud_vertex(p.lights, {0, 0, 0}, apply_normal_transform(job.nt, m.normals[set[k]]));
        return;
    }
#endif
    for (std::size_t k = 0; k < set.count; ++k) {
        const std::uint32_t i = set[k];
        xvertex &x = vertices[i];
        vec3_t world{0, 0, 0}, normal{0, 0, 0};
        if (job.gouraud || job.generic) {
            world = mul3(p.model, m.positions[i]);
            normal = apply_normal_transform(job.nt, m.normals[i]);
        }
        x.shade = job.gouraud ? shade_gouraud_vertex(p.lights, world, normal) : 0.0f;
        if (job.generic) {
            float *a = &vertex_attr[i * ATTR_COUNT];
            a[ATTR_PX] = world.x, a[ATTR_PY] = world.y, a[ATTR_PZ] = world.z;
            a[ATTR_NX] = normal.x, a[ATTR_NY] = normal.y, a[ATTR_NZ] = normal.z;
            a[ATTR_U] = m.uvs[i].x, a[ATTR_V] = m.uvs[i].y;
            a[ATTR_SHADE] = x.shade;
        }
    }
}

// ---- phase 1b: triangles -------------------------------------------------------------------

// One convex polygon (already inside the near/far planes and the guard band) as a fan;
// `count`: add its triangles to the stats.
void render_context::impl::emit(const clip_vertex *poly, int n, const draw_params &p, std::uint32_t state,
                                bool generic, bool count, segment &out) {
    const float half_w = 0.5f * static_cast<float>(target->width), half_h = 0.5f * static_cast<float>(target->height);
    const pixel_rect full{0, 0, target->width, target->height};
    for (int k = 1; k + 1 < n; ++k) {
        const clip_vertex *c[3] = {&poly[0], &poly[k], &poly[k + 1]};
        const screen_vertex v[3] = {to_screen(c[0]->position, half_w, half_h), to_screen(c[1]->position, half_w, half_h),
                                    to_screen(c[2]->position, half_w, half_h)};
        const triangle_edges t = triangle_setup(v[0], v[1], v[2], full, p.cull);
        if (!t.valid) {
            out.stats.culled_backface += count && t.culled;
            continue;
        }
        out.stats.rasterized += count;
        if (generic) {
            generic_triangle g;
            for (int j = 0; j < 3; ++j) {
                g.v[j] = v[j];
                for (int a = 0; a < ATTR_COUNT; ++a) g.attr[j][a] = c[j]->attr[a];
            }
            g.mean_depth = (v[0].z + v[1].z + v[2].z) / 3.0f;
            g.state = state;
            g.sequence = 0;
            out.generic.push_back(g);
            continue;
        }
        const float shade[3] = {c[0]->attr[ATTR_SHADE], c[1]->attr[ATTR_SHADE], c[2]->attr[ATTR_SHADE]};
        const float depth[3] = {v[0].z, v[1].z, v[2].z};
        add_fast(t, depth, shade, out);
    }
}

// Thread `thread` walks every triangle but sets up only the fast ones that reach its bands
// (and every clipped or per-pixel-path one: rare, and cheap to repeat); each triangle is
// counted in the stats by one thread only (thread 0, or for fast triangles the owner of the
// first row's band). With clusters (`view` not null), whole chunks are decided first: a
// chunk proven back-facing is skipped by every thread and counted by one; a chunk inside the
// guard band is walked only by the threads drawing a band among its rows, and its culled
// triangles are counted by the owner of its first row's band (thread 0 when it has no row
// on the target) — the same counts as walking every triangle.
void render_context::impl::setup(const raster_mesh &m, const draw_params &p, const vertex_job &job, std::uint32_t state,
                                 int thread, const detail::cluster_view *view, segment &out) {
    if (!view) {
        transform(m, p, job, {nullptr, m.positions.size()}, out);
        setup_range(m, p, state, job.generic, thread, thread == 0, 0, m.triangles.size(), out);
        return;
    }
    // First decide every chunk, then transform: the vertices of the walked chunks one chunk
    // at a time when they are fewer than the mesh's (a vertex shared by two walked chunks is
    // transformed twice), else every vertex at once (meshes whose chunks are rarely skipped).
    const std::vector<raster_cluster> &chunks = p.clusters->clusters();
    out.chunks.resize(chunks.size());
    std::size_t walked_vertices = 0;
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        const raster_cluster &c = chunks[k];
        const detail::cluster_verdict v = detail::classify_cluster(*view, c);
        const bool on_target = v.inside && v.row0 <= v.row1;
        const int counter = on_target ? band_owner[band_of(v.row0)] : 0;
        chunk_walk &decision = out.chunks[k];
        decision = {false, thread == counter};
        if (v.back) {
            if (decision.counts) {
                out.stats.culled_backface += c.count;
                out.stats.backface_by_cluster += c.count;
            }
            continue;
        }
        decision.walk = !v.inside || decision.counts || (on_target && draws_rows(thread, v.row0, v.row1));
        if (decision.walk) walked_vertices += c.vertex_count;
    }
    const bool per_chunk = walked_vertices < m.positions.size();
    if (!per_chunk) transform(m, p, job, {nullptr, m.positions.size()}, out);
    const std::uint32_t *chunk_vertices = p.clusters->vertices().data();
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        if (!out.chunks[k].walk) continue;
        const raster_cluster &c = chunks[k];
        if (per_chunk) transform(m, p, job, {chunk_vertices + c.vertex_first, c.vertex_count}, out);
        setup_range(m, p, state, job.generic, thread, out.chunks[k].counts, c.first, c.first + c.count, out);
    }
}

// setup() for triangles [first, last); `counts_all`: this thread counts culled and clipped ones.
void render_context::impl::setup_range(const raster_mesh &m, const draw_params &p, std::uint32_t state, bool generic,
                                       int thread, bool counts_all, std::size_t first, std::size_t last,
                                       segment &out) {
    const bool flat = p.shade == shading::flat;
    const std::vector<xvertex> &vertices = out.vertices;
    const std::vector<float> &vertex_attr = out.vertex_attr;
    const pixel_rect full{0, 0, target->width, target->height};
    const std::int64_t last_row = target->height - 1;
    for (std::size_t i = first; i < last; ++i) {
        const std::array<std::uint32_t, 3> &tri = m.triangles[i];
        const xvertex &a = vertices[tri[0]], &b = vertices[tri[1]], &c = vertices[tri[2]];
        if (a.outcode & b.outcode & c.outcode) continue;  // all outside one plane
        float flat_shade = 0.0f;
        if (flat) flat_shade = shade_flat(p.lights, mul3(p.model, m.positions[tri[0]]), mul3(p.model, m.positions[tri[1]]),
                                          mul3(p.model, m.positions[tri[2]]));
        if ((a.outcode | b.outcode | c.outcode) == 0 && !generic) {
            // The common case: no clipping, straight to the fast setup.
            // Snapped once per vertex in transform(); an unusable vertex skips the triangle
            // exactly as triangle_setup would.
            if (!(a.snapped && b.snapped && c.snapped)) continue;
            const std::int32_t X[3] = {a.snapped_x, b.snapped_x, c.snapped_x};
            const std::int32_t Y[3] = {a.snapped_y, b.snapped_y, c.snapped_y};
            // Cheap early rejection on the snapped 2-D cross product (the same sign test
            // triangle_setup makes), before the full edge setup.
            const std::int64_t area2 = detail::snapped_area2(X, Y);
            if (area2 == 0) continue;
            if (detail::facing_culled(area2, p.cull)) {
                out.stats.culled_backface += counts_all;
                continue;
            }
            // Candidate rows (pixel centres 16·row + 8 within the snapped y range): skip the
            // triangle when this thread draws none of their bands.
            const std::int64_t row0 = std::max<std::int64_t>(
                -((RASTER_SUBPIXEL_ONE / 2 - std::min({Y[0], Y[1], Y[2]})) >> RASTER_SUBPIXEL_BITS), 0);
            const std::int64_t row1 = std::min<std::int64_t>(
                (std::max({Y[0], Y[1], Y[2]}) - RASTER_SUBPIXEL_ONE / 2) >> RASTER_SUBPIXEL_BITS, last_row);
            if (row0 > row1 || !draws_rows(thread, static_cast<int>(row0), static_cast<int>(row1))) continue;
            const bool counts = band_owner[band_of(static_cast<int>(row0))] == thread;
            const float depth[3] = {a.depth, b.depth, c.depth};
            const float shade[3] = {flat ? flat_shade : a.shade, flat ? flat_shade : b.shade, flat ? flat_shade : c.shade};
            detail::fast_triangle f;
            const detail::fast_setup verdict = detail::setup_fast_triangle(X, Y, area2, full, depth, shade, f);
            if (verdict == detail::fast_setup::ready) {
                out.stats.rasterized += counts;
                bin_fast(f, out);
            } else if (verdict == detail::fast_setup::wide) {
                const triangle_edges t = detail::triangle_setup_snapped(X, Y, full, p.cull);
                if (!t.valid) continue;
                out.stats.rasterized += counts;
                add_fast(t, depth, shade, out);
            }
            continue;
        }
        clip_vertex in[3];
        for (int j = 0; j < 3; ++j) {
            const xvertex &x = vertices[tri[j]];
            in[j].position = out.clip[tri[j]];
            in[j].attr.fill(0.0f);
            if (generic)
                for (int s = 0; s < ATTR_COUNT; ++s) in[j].attr[s] = vertex_attr[tri[j] * ATTR_COUNT + s];
            in[j].attr[ATTR_SHADE] = flat ? flat_shade : x.shade;
        }
        const unsigned planes = a.outcode | b.outcode | c.outcode;
        if (planes) out.stats.clipped += counts_all;
        clip_vertex poly[CLIP_MAX_VERTICES];
        const int n = planes ? clip_polygon(in, 3, planes, guard, ATTR_COUNT, poly) : 3;
        emit(planes ? poly : in, n, p, state, generic, counts_all, out);
    }
}

// ---- phase 2: per-pixel path ----------------------------------------------------------------

void render_context::impl::draw_generic(const generic_triangle &g, int y0, int y1) {
    const draw_params &p = states[g.state].params;
    const bool translucent = p.alpha < 1.0f;
    const float alpha = std::clamp(p.alpha, 0.0f, 1.0f);
    const pixel_rect band{0, y0, target->width, y1};
    const bool trilinear = p.tex && p.filter == texture_filter::trilinear;
    detail::uv_derivatives uv_d;
    if (trilinear) {
        const float u[3] = {g.attr[0][ATTR_U], g.attr[1][ATTR_U], g.attr[2][ATTR_U]};
        const float v[3] = {g.attr[0][ATTR_V], g.attr[1][ATTR_V], g.attr[2][ATTR_V]};
        uv_d = detail::uv_derivatives::of(g.v, u, v, p.perspective_correct);
    }
    rasterize_triangle(g.v[0], g.v[1], g.v[2], band, [&](int x, int y, float l0, float l1, float l2) {
        const float z = l0 * g.v[0].z + l1 * g.v[1].z + l2 * g.v[2].z;
        float *zp = depth.row(y) + x;
        if (!detail::depth_passes(p.depth, z, *zp)) return;
        // Perspective-correct weights: l_k/w_k normalised (attr/w and 1/w interpolated).
        float w0 = l0, w1 = l1, w2 = l2, inv_b = 1.0f;
        if (p.perspective_correct) {
            w0 = l0 * g.v[0].inv_w, w1 = l1 * g.v[1].inv_w, w2 = l2 * g.v[2].inv_w;
            inv_b = 1.0f / (w0 + w1 + w2);
            w0 *= inv_b, w1 *= inv_b, w2 *= inv_b;
        }
        auto lerp = [&](int slot) { return w0 * g.attr[0][slot] + w1 * g.attr[1][slot] + w2 * g.attr[2][slot]; };
        float shade;
        if (p.shade == shading::phong)
            shade = shade_phong_pixel(p.lights, {lerp(ATTR_PX), lerp(ATTR_PY), lerp(ATTR_PZ)},
                                      {lerp(ATTR_NX), lerp(ATTR_NY), lerp(ATTR_NZ)});
        else shade = lerp(ATTR_SHADE);
        if (trilinear) {
            const float u = lerp(ATTR_U), v = lerp(ATTR_V);
            shade *= texture_sample_trilinear(*p.tex, u, v, uv_d.lod(*p.tex, u, v, inv_b), p.wrap);
        } else if (p.tex) {
            shade *= texture_sample(*p.tex, lerp(ATTR_U), lerp(ATTR_V), p.filter, p.wrap);
        }
        float &dst = target->pixels[y][x];
        if (translucent) {
            dst = detail::clamp01(alpha * shade + (1.0f - alpha) * dst);
        } else {
            dst = detail::clamp01(shade);
            *zp = z;
        }
    });
}

// ---- the public class -------------------------------------------------------------------------

render_context::render_context(int threads) : impl_(std::make_unique<impl>(std::clamp(threads, 1, MAX_THREADS))) {}
render_context::~render_context() = default;
int render_context::threads() const { return impl_->pool.size(); }
const zbuffer &render_context::depth() const { return impl_->depth; }
const frame_stats &render_context::stats() const { return impl_->stats; }

status render_context::begin_frame(canvas_t &target, float clear_intensity) {
    impl &s = *impl_;
    if (!target.pixels || !target.data) return error{"", 0, -1, "render_context: canvas has no pixels"};
    const status size_ok = s.depth.resize(target.width, target.height);
    if (!size_ok) return size_ok;
    s.target = &target;
    s.clear_intensity = detail::clamp01(clear_intensity);
    s.pending_clear = true;
    s.stats = {};
    s.states.clear();
    s.translucent.clear();
    s.band_count = std::clamp(target.height / BAND_ROWS, s.pool.size(), MAX_BANDS);
    s.band_count = std::min(s.band_count, std::max(target.height, 1));
    if (s.row_band.size() < static_cast<std::size_t>(target.height)) s.row_band.resize(target.height);
    for (int b = 0; b < s.band_count; ++b)
        for (int y = s.band_y0(b); y < s.band_y0(b + 1); ++y) s.row_band[static_cast<std::size_t>(y)] = static_cast<std::uint8_t>(b);
    // Threads own blocks of neighbouring bands, dealt in turn (BLOCKS_PER_THREAD each when
    // there are enough bands): few triangles straddle two owners, and the load stays even
    // when the scene is not.
    const int n = s.pool.size();
    const int block = std::max(1, s.band_count / (BLOCKS_PER_THREAD * n));
    for (int b = 0; b < s.band_count; ++b) s.band_owner[b] = static_cast<std::uint8_t>(b / block % n);
    s.guard = std::clamp(GUARD_SPAN_PIXELS / static_cast<float>(std::max(target.width, target.height)), 1.0f, MAX_GUARD);
    return {};
}

void render_context::draw(const raster_mesh &mesh, const draw_params &params) {
    impl &s = *impl_;
    if (!s.target || mesh.positions.size() != mesh.normals.size() || mesh.positions.size() != mesh.uvs.size()) return;
    s.stats.triangles_in += mesh.triangles.size();
    const mat4_t mvp = mat4_multiply(params.view_projection, params.model);
    const bool outside = sphere_outside(mvp, mesh.bound_center, mesh.bound_radius);
    if (outside) {
        s.stats.culled_frustum += mesh.triangles.size();
        return;
    }
    if (!indices_below(mesh.triangles, mesh.positions.size())) return;
    const bool generic = params.shade == shading::phong || params.tex != nullptr || params.alpha < 1.0f;
    const std::uint32_t state = static_cast<std::uint32_t>(s.states.size());
    s.states.push_back({params});
    const std::size_t nv = mesh.positions.size();
    const int n = s.pool.size();
    // Cluster culling for the fast path, when the clusters were built from this mesh.
    const raster_clusters *clusters = params.clusters;
    const bool use_clusters = clusters && !generic && clusters->vertex_count() == nv &&
                              clusters->triangle_count() == mesh.triangles.size();
    detail::cluster_view cluster_view{};
    if (use_clusters) cluster_view = detail::make_cluster_view(mvp, s.target->width, s.target->height, s.guard, params.cull);
    const detail::cluster_view *view = use_clusters ? &cluster_view : nullptr;
    const vertex_job job = s.make_vertex_job(params, mvp, generic);
    for (int t = 0; t < n; ++t) {
        impl::segment &seg = s.segments[t];
        if (seg.vertices.size() < nv) seg.vertices.resize(nv), seg.clip.resize(nv);
        if (generic && seg.vertex_attr.size() < nv * ATTR_COUNT) seg.vertex_attr.resize(nv * ATTR_COUNT);
    }
    // One phase: each thread transforms every vertex (with clusters: those of the chunks it
    // walks) into its own segment (repeating that cheap pass costs less than sharing vertex
    // lines between cores), sets up the triangles that reach its bands and draws its bands
    // from its own segment.
    auto phase_triangles = [&](int t) {
        impl::segment &seg = s.segments[t];
        seg.fast.clear();
        seg.wide.clear();
        seg.generic.clear();
        seg.stats = {};
        for (int b = 0; b < s.bands(); ++b) seg.bins[b].clear();
        s.setup(mesh, params, job, state, t, view, seg);
        s.segment_ready[t].serial.store(s.draw_serial, std::memory_order_release);
        auto draw_band = [&](int band, const impl::segment &from) {
            const int y0 = s.band_y0(band), y1 = s.band_y0(band + 1);
            if (s.pending_clear) s.clear_band(band);
            for (std::uint32_t index : from.bins[band]) {
                const detail::fast_triangle &f = from.fast[index];
                detail::fill_fast_rows(*s.target, &s.depth, f, f.wide >= 0 ? &from.wide[f.wide] : nullptr, params.depth,
                                       true, y0, y1);
            }
            if (params.alpha >= 1.0f)
                for (const generic_triangle &g : from.generic) s.draw_generic(g, y0, y1);
        };
        for (int band = 0; band < s.bands(); ++band)
            if (s.band_owner[band] == t && s.claim_band(band)) draw_band(band, seg);
        // Then help: the other threads' bands not yet claimed, from their last band backwards
        // (their owners go forwards), each once its owner's segment is set up.
        for (int k = 1; k < n; ++k) {
            const int owner = (t + k) % n;
            const impl::segment &from = s.segments[owner];
            bool ready = false;
            for (int band = s.bands() - 1; band >= 0; --band) {
                if (s.band_owner[band] != owner || s.band_claim[band].load(std::memory_order_relaxed) == s.draw_serial)
                    continue;
                if (!ready) {
                    spin_until_yielding([&] {
                        return s.segment_ready[owner].serial.load(std::memory_order_acquire) == s.draw_serial;
                    });
                    ready = true;
                }
                if (s.claim_band(band)) draw_band(band, from);
            }
        }
    };
    if (++s.draw_serial == 0) {  // wrapped: 0 is what the flags start from
        for (auto &claim : s.band_claim) claim.store(0, std::memory_order_relaxed);
        for (auto &ready : s.segment_ready) ready.serial.store(0, std::memory_order_relaxed);
        s.draw_serial = 1;
    }  // published to the workers by pool.run
    s.pool.run(phase_triangles);
    if (params.alpha < 1.0f)  // every segment holds all per-pixel-path triangles: take segment 0's
        for (generic_triangle g : s.segments[0].generic) {
            g.sequence = static_cast<std::uint32_t>(s.translucent.size());
            s.translucent.push_back(g);
        }
    s.pending_clear = false;
    for (int t = 0; t < n; ++t) {
        const frame_stats &st = s.segments[t].stats;
        s.stats.culled_backface += st.culled_backface;
        s.stats.clipped += st.clipped;
        s.stats.rasterized += st.rasterized;
        s.stats.backface_by_cluster += st.backface_by_cluster;
    }
}

void render_context::end_frame() {
    impl &s = *impl_;
    if (!s.target) return;
    // Back to front; equal depths keep submission order (std::sort: no temporary buffer).
    std::sort(s.translucent.begin(), s.translucent.end(), [](const generic_triangle &a, const generic_triangle &b) {
        return a.mean_depth != b.mean_depth ? a.mean_depth > b.mean_depth : a.sequence < b.sequence;
    });
    if (s.translucent.empty() && !s.pending_clear) {
        s.target = nullptr;
        return;
    }
    auto phase = [&](int thread) {
        for (int band = 0; band < s.bands(); ++band) {
            if (s.band_owner[band] != thread) continue;
            const int y0 = s.band_y0(band), y1 = s.band_y0(band + 1);
            if (s.pending_clear) s.clear_band(band);
            for (const generic_triangle &g : s.translucent) s.draw_generic(g, y0, y1);
        }
    };
    s.pool.run(phase);
    s.pending_clear = false;
    s.translucent.clear();
    s.target = nullptr;
}

}  // namespace tiny3d
