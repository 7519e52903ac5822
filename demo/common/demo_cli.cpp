// demo_cli.cpp — see demo_cli.h.
#include "demo_cli.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace demo {
namespace {

bool parse_int(const std::string &s, int &out) {
    if (s.empty()) return false;
    char *end = nullptr;
    errno = 0;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || v < -2147483647L || v > 2147483647L) return false;
    out = int(v);
    return true;
}

tiny3d::error usage_error(const std::string &what) { return tiny3d::error{"", 0, -1, what}; }

}  // namespace

tiny3d::result<options> parse(int argc, char **argv, const std::string &name, int default_width,
                              int default_height, int frame_count) {
    options o;
    o.name = name;
    o.out_dir = "build/frames/" + name;
    o.width = default_width;
    o.height = default_height;
    o.frame_count = frame_count;
    o.first_frame = 0;
    o.last_frame = frame_count - 1;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        std::string key = a, value;
        bool has_inline = false;
        if (a.rfind("--", 0) == 0 && a.find('=') != std::string::npos) {
            key = a.substr(0, a.find('='));
            value = a.substr(a.find('=') + 1);
            has_inline = true;
        }
        if (key == "--out" || key == "--frames" || key == "--size") {
            if (!has_inline) {
                if (i + 1 >= argc) return usage_error(key + " needs a value");
                value = argv[++i];
            }
            if (key == "--out") {
                if (value.empty()) return usage_error("--out needs a folder");
                o.out_dir = value;
            } else if (key == "--size") {
                const auto x = value.find_first_of("xX");
                int w = 0, h = 0;
                if (x == std::string::npos || !parse_int(value.substr(0, x), w) ||
                    !parse_int(value.substr(x + 1), h))
                    return usage_error("--size wants WxH (e.g. 640x480), got '" + value + "'");
                if (tiny3d::status s = tiny3d::check_canvas_size(w, h); !s) return usage_error("--size: " + s.message());
                o.width = w;
                o.height = h;
            } else {
                const auto colon = value.find(':');
                int a0 = 0, b0 = 0;
                if (colon == std::string::npos || !parse_int(value.substr(0, colon), a0) ||
                    !parse_int(value.substr(colon + 1), b0))
                    return usage_error("--frames wants A:B (e.g. 0:29), got '" + value + "'");
                if (a0 < 0 || b0 < a0 || b0 >= frame_count)
                    return usage_error("--frames " + value + ": the range must lie within 0:" +
                                       std::to_string(frame_count - 1) + " with A <= B");
                o.first_frame = a0;
                o.last_frame = b0;
            }
        } else {
            o.rest.push_back(a);
        }
    }
    return o;
}

bool take_flag(options &o, const std::string &flag) {
    auto it = std::find(o.rest.begin(), o.rest.end(), flag);
    if (it == o.rest.end()) return false;
    o.rest.erase(it);
    return true;
}

std::optional<std::string> take_value(options &o, const std::string &key) {
    for (std::size_t i = 0; i < o.rest.size(); ++i) {
        const std::string &a = o.rest[i];
        if (a.rfind(key + "=", 0) == 0) {
            std::string v = a.substr(key.size() + 1);
            o.rest.erase(o.rest.begin() + long(i));
            return v;
        }
        if (a == key && i + 1 < o.rest.size()) {
            std::string v = o.rest[i + 1];
            o.rest.erase(o.rest.begin() + long(i), o.rest.begin() + long(i) + 2);
            return v;
        }
    }
    return std::nullopt;
}

tiny3d::status check_no_rest(const options &o, const std::string &usage) {
    if (o.rest.empty()) return {};
    return usage_error("unexpected argument '" + o.rest.front() + "'\nusage: " + usage);
}

std::string frame_path(const options &o, int frame, const std::string &prefix) {
    char num[32];
    std::snprintf(num, sizeof num, "%03d", frame);
    return o.out_dir + "/" + prefix + num + ".pgm";
}

tiny3d::status prepare_out_dir(const options &o) {
    std::error_code ec;
    std::filesystem::create_directories(o.out_dir, ec);
    if (ec) return tiny3d::error{o.out_dir, 0, -1, "cannot create the output folder: " + ec.message()};
    return {};
}

tiny3d::status save_frame(const canvas_t &canvas, const std::string &path) {
    tiny3d::status s = tiny3d::save_pgm(canvas, path);
    if (s) std::printf("wrote %s\n", path.c_str());
    return s;
}

void frame_timer::start() { t0_ = std::chrono::steady_clock::now(); }

void frame_timer::stop() {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count();
    ms_.push_back(ms);
    std::fprintf(stderr, "\r%s: frame %zu/%d  %.2f ms", name_.c_str(), ms_.size(), total_, ms);
    if (int(ms_.size()) == total_) std::fprintf(stderr, "\n");
}

void frame_timer::report() const {
    if (ms_.empty()) return;
    std::vector<double> s = ms_;
    std::sort(s.begin(), s.end());
    const double median = s.size() % 2 ? s[s.size() / 2] : 0.5 * (s[s.size() / 2 - 1] + s[s.size() / 2]);
    std::fprintf(stderr, "%s: %zu frames, ms per frame min %.2f / median %.2f / max %.2f (%.1f / %.1f / %.1f fps)\n",
                 name_.c_str(), s.size(), s.front(), median, s.back(), 1000.0 / s.front(), 1000.0 / median,
                 1000.0 / s.back());
}

int fail(const std::string &demo_name, const std::string &message) {
    std::fprintf(stderr, "%s: %s\n", demo_name.c_str(), message.c_str());
    return 1;
}

int fail(const options &o, const std::string &message) { return fail(o.name, message); }

}  // namespace demo
