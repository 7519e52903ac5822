// demo_cli.cpp — see demo_cli.h.
#include "demo_cli.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "animation.h"
#include "canvas.h"  // save_pgm, save_png
#include "math3d.h"
#include "raster.h"
#include "wireframe.h"

namespace demo {
namespace {

std::string in_quotes(const std::string &text) { return "'" + text + "'"; }

bool starts_with_space(const std::string &text) {
    return !text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n');
}

// GIF delays are whole hundredths of a second, and viewers slow 0 or 1 down to 10.
constexpr double kGifMaxFps = 50.0;

std::string number_text(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string range_text(double min, double max) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%g..%g", min, max);
    return buf;
}

// "A:B" → two integers.
bool split_pair(const std::string &text, char separator, std::string &first, std::string &second) {
    const auto at = text.find(separator);
    if (at == std::string::npos) return false;
    first = text.substr(0, at);
    second = text.substr(at + 1);
    return true;
}

}  // namespace

std::string parse_int(const std::string &option, const std::string &text, long min, long max, long &out) {
    const std::string wanted = option + " wants an integer in " + std::to_string(min) + ".." + std::to_string(max) +
                               ", got " + in_quotes(text);
    if (text.empty() || starts_with_space(text)) return wanted;
    char *end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || v < min || v > max) return wanted;
    out = v;
    return "";
}

std::string parse_number(const std::string &option, const std::string &text, double min, double max, double &out) {
    const std::string wanted = option + " wants a number in " + range_text(min, max) + ", got " + in_quotes(text);
    if (text.empty() || starts_with_space(text)) return wanted;
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    // strtod accepts "nan", "inf" and hexadecimal floats; the range check refuses the first
    // two, ERANGE refuses overflow (1e999) and underflow to a denormal.
    if (*end != '\0' || errno == ERANGE || !std::isfinite(v) || v < min || v > max) return wanted;
    out = v;
    return "";
}

std::string parse_vec3(const std::string &option, const std::string &text, vec3_t &out) {
    const std::string wanted = option + " wants X,Y,Z (three numbers), got " + in_quotes(text);
    std::string x, yz, y, z;
    if (!split_pair(text, ',', x, yz) || !split_pair(yz, ',', y, z)) return wanted;
    double v[3];
    const std::string parts[3] = {x, y, z};
    for (int k = 0; k < 3; ++k)
        if (!parse_number(option, parts[k], -1e30, 1e30, v[k]).empty()) return wanted;
    out = vec3_t{float(v[0]), float(v[1]), float(v[2])};
    return "";
}

command_line::command_line(std::string name, std::string synopsis, std::string description)
    : name_(std::move(name)), synopsis_(std::move(synopsis)), description_(std::move(description)) {
    add({"--help", "", "print this help and exit", false, false, nullptr});
}

command_line::option *command_line::find(const std::string &name) {
    for (option &o : options_)
        if (o.name == name) return &o;
    return nullptr;
}

void command_line::add(option o) { options_.push_back(std::move(o)); }

void command_line::add_out() {
    common.out_dir = "build/frames/" + name_;
    add({"--out", "DIR", "folder for the images, created if missing (default " + common.out_dir + ")", true, false,
         [this](const std::string &v) -> std::string {
             if (v.empty()) return "--out wants a folder, got ''";
             common.out_dir = v;
             common.out_given = true;
             return "";
         }});
}

void command_line::add_size(int default_width, int default_height) {
    common.width = default_width;
    common.height = default_height;
    add({"--size", "WxH",
         "image size in pixels (default " + std::to_string(default_width) + "x" + std::to_string(default_height) + ")",
         true, false, [this](const std::string &v) -> std::string {
             const std::string wanted = "--size wants WxH (e.g. 640x480), got " + in_quotes(v);
             std::string w_text, h_text;
             long w = 0, h = 0;
             if (!split_pair(v, 'x', w_text, h_text) && !split_pair(v, 'X', w_text, h_text)) return wanted;
             if (!parse_int("--size", w_text, 1, 1 << 20, w).empty() ||
                 !parse_int("--size", h_text, 1, 1 << 20, h).empty())
                 return wanted;
             if (tiny3d::status s = tiny3d::check_canvas_size(int(w), int(h)); !s)
                 return "--size " + v + ": " + s.message();
             common.width = int(w);
             common.height = int(h);
             return "";
         }});
}

void command_line::add_frames(std::function<int()> frame_count) {
    frame_count_ = std::move(frame_count);
    add({"--frames", "A:B", "render only frames A to B (inclusive, 0-based; frame k is the same image in any range)",
         true, false, [this](const std::string &v) -> std::string {
             frames_text_ = v;
             std::string a, b;
             long first = 0, last = 0;
             if (!split_pair(v, ':', a, b) || !parse_int("--frames", a, 0, 1L << 30, first).empty() ||
                 !parse_int("--frames", b, 0, 1L << 30, last).empty())
                 return "--frames wants A:B (e.g. 0:29), got " + in_quotes(v);
             common.first_frame = int(first);
             common.last_frame = int(last);
             return "";
         }});
}

void command_line::add_threads(int default_threads) {
    common.threads = default_threads;
    integer("--threads", common.threads, 1, 16, "worker threads, 1..16 (default " + std::to_string(default_threads) + ")");
}

void command_line::add_samples(tiny3d::sample_count default_samples) {
    common.samples = default_samples;
    custom("--aa", "N",
           "anti-aliasing: samples per pixel of the filled triangles, 1 (aliased), 4, 8 or 16 (default " +
               std::to_string(static_cast<int>(default_samples)) + "; lines are always anti-aliased)",
           [this](const std::string &text) {
               const tiny3d::result<tiny3d::sample_count> n = tiny3d::parse_sample_count(text);
               if (!n) return "--aa wants 1, 4, 8 or 16, got '" + text + "'";
               common.samples = n.value();
               return std::string();
           });
}

void command_line::add_png() {
    flag("--png", common.png, "write a PNG beside every PGM (same name, .png); the PGM is always written");
}

void command_line::add_gif() {
    text("--gif", "FILE", common.gif_path,
         "also write the frames as one animated GIF (lossless 256 greys, looping); the PGM frames are then "
         "written only if --out is given too");
    number("--fps", common.fps, 0.1, 1000.0,
           "frames per second of the sequence: frame k shows at k / X seconds, the GIF's rate (default 30; "
           "at most 50 with --gif)");
}

void command_line::add_sequence_options(int frame_count, int default_width, int default_height) {
    add_sequence_options(std::function<int()>([frame_count] { return frame_count; }), default_width, default_height);
}

void command_line::add_sequence_options(std::function<int()> frame_count, int default_width, int default_height) {
    add_out();
    add_frames(std::move(frame_count));
    add_size(default_width, default_height);
    add_png();
    add_gif();
}

void command_line::flag(const std::string &name, bool &target, const std::string &help) {
    add({name, "", help, false, false, [&target](const std::string &) -> std::string {
             target = true;
             return "";
         }});
}

namespace {

// The setter of a numeric option: `parse` reads the value as a Wide (long or double) within
// [min, max]; on success the target takes it converted to its own type.
template <class T, class Wide>
std::function<std::string(const std::string &)> numeric_setter(
    T &target, std::string (*parse)(const std::string &, const std::string &, Wide, Wide, Wide &), std::string name,
    Wide min, Wide max) {
    return [&target, parse, name, min, max](const std::string &v) {
        Wide out = 0;
        std::string e = parse(name, v, min, max, out);
        if (e.empty()) target = T(out);
        return e;
    };
}

}  // namespace

void command_line::integer(const std::string &name, int &target, int min, int max, const std::string &help) {
    add({name, "N", help, true, false, numeric_setter<int, long>(target, parse_int, name, min, max)});
}

void command_line::number(const std::string &name, double &target, double min, double max, const std::string &help) {
    add({name, "X", help, true, false, numeric_setter<double, double>(target, parse_number, name, min, max)});
}

void command_line::number(const std::string &name, float &target, float min, float max, const std::string &help) {
    add({name, "X", help, true, false, numeric_setter<float, double>(target, parse_number, name, min, max)});
}

void command_line::choice(const std::string &name, std::string &target, std::vector<std::string> choices,
                          const std::string &help) {
    std::string metavar;
    for (const std::string &c : choices) metavar += (metavar.empty() ? "" : "|") + c;
    add({name, metavar, help, true, false, [&target, name, choices, metavar](const std::string &v) -> std::string {
             if (std::find(choices.begin(), choices.end(), v) == choices.end())
                 return name + " wants one of " + metavar + ", got " + in_quotes(v);
             target = v;
             return "";
         }});
}

void command_line::text(const std::string &name, const std::string &metavar, std::string &target,
                        const std::string &help) {
    add({name, metavar, help, true, false, [&target, name](const std::string &v) -> std::string {
             if (v.empty()) return name + " wants a value, got ''";
             target = v;
             return "";
         }});
}

void command_line::vector3(const std::string &name, vec3_t &target, bool &given, const std::string &help) {
    add({name, "X,Y,Z", help, true, false, [&target, &given, name](const std::string &v) {
             std::string e = parse_vec3(name, v, target);
             if (e.empty()) given = true;
             return e;
         }});
}

void command_line::vector3_list(const std::string &name, std::vector<vec3_t> &target, const std::string &help) {
    add({name, "X,Y,Z", help, true, true, [&target, name](const std::string &v) {
             vec3_t p{};
             std::string e = parse_vec3(name, v, p);
             if (e.empty()) target.push_back(p);
             return e;
         }});
}

void command_line::custom(const std::string &name, const std::string &metavar, const std::string &help,
                          std::function<std::string(const std::string &)> set, bool repeatable) {
    add({name, metavar, help, !metavar.empty(), repeatable, std::move(set)});
}

void command_line::positional(const std::string &metavar, std::string &target, bool required) {
    positionals_.push_back({metavar, &target, required});
}

std::string command_line::help() const {
    std::string usage = "usage: " + name_;
    if (!synopsis_.empty()) usage += " " + synopsis_;
    usage += " [options]\n\n" + description_ + "\n\noptions:\n";
    constexpr std::size_t help_column = 24, line_width = 92;
    for (const option &o : options_) {
        std::string line = "  " + o.name + (o.metavar.empty() ? "" : " " + o.metavar);
        if (line.size() + 2 > help_column) {
            usage += line + "\n";
            line.clear();
        }
        line.resize(help_column, ' ');
        // Word-wrapped help, continuation lines under the first.
        std::string words = o.help + (o.repeatable ? " (repeatable)" : ""), word;
        std::size_t at = 0;
        bool first = true;
        while (at < words.size()) {
            const std::size_t space = std::min(words.find(' ', at), words.size());
            word = words.substr(at, space - at);
            at = space + 1;
            if (!first && line.size() + 1 + word.size() > line_width) {
                usage += line + "\n";
                line.assign(help_column, ' ');
                first = true;
            }
            line += (first ? "" : " ") + word;
            first = false;
        }
        usage += line + "\n";
    }
    usage += "\nExit status: 0 done, 1 failed while running, 2 bad command line (nothing written).\n";
    return usage;
}

int command_line::usage_error(const std::string &message) const {
    std::fprintf(stderr, "%s: %s\n(%s --help lists the options)\n", name_.c_str(), message.c_str(), name_.c_str());
    return EXIT_USAGE;
}

int command_line::fail(const std::string &message) const {
    std::fprintf(stderr, "%s: %s\n", name_.c_str(), message.c_str());
    return EXIT_FAILURE_RUN;
}

int command_line::parse(int argc, char **argv) {
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            std::fputs(help().c_str(), stdout);
            return 0;
        }
    std::vector<std::string> positional_values;
    bool options_done = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (options_done || arg.size() < 2 || arg[0] != '-' || (arg[1] != '-' && !std::isalpha((unsigned char)arg[1]))) {
            positional_values.push_back(arg);  // "-5" and "-" are values, not options
            continue;
        }
        if (arg == "--") {
            options_done = true;
            continue;
        }
        const auto eq = arg.find('=');
        const std::string key = arg.substr(0, eq);
        option *o = find(key);
        if (!o) return usage_error("unknown option " + in_quotes(key));
        std::string value;
        if (eq != std::string::npos) {
            if (!o->takes_value) return usage_error(key + " takes no value, got " + in_quotes(arg));
            value = arg.substr(eq + 1);
        } else if (o->takes_value) {
            if (i + 1 >= argc) return usage_error(key + " needs a value (" + o->metavar + ")");
            value = argv[++i];
        }
        if (std::string e = o->set(value); !e.empty()) return usage_error(e);
    }
    std::size_t required = 0;
    for (const positional_arg &p : positionals_) required += p.required;
    if (positional_values.size() < required)
        return usage_error("missing " + positionals_[positional_values.size()].metavar);
    if (positional_values.size() > positionals_.size())
        return usage_error("unexpected argument " + in_quotes(positional_values[positionals_.size()]));
    for (std::size_t k = 0; k < positional_values.size(); ++k) *positionals_[k].target = positional_values[k];

    if (!common.gif_path.empty() && common.fps > kGifMaxFps)
        return usage_error("--fps " + number_text(common.fps) + " is too fast for a GIF: at most 50 with --gif");
    if (frame_count_) {
        common.frame_count = frame_count_();
        if (frames_text_.empty()) {
            common.first_frame = 0;
            common.last_frame = common.frame_count - 1;
        } else if (common.first_frame > common.last_frame || common.last_frame >= common.frame_count) {
            return usage_error("--frames " + frames_text_ + ": the range must lie within 0:" +
                               std::to_string(common.frame_count - 1) + " with A <= B");
        }
    }
    return -1;
}

tiny3d::status prepare_out_dir(const common_options &o) {
    if (!o.write_frames()) return {};  // only a GIF: no folder of frames
    std::error_code ec;
    std::filesystem::create_directories(o.out_dir, ec);
    if (ec) return tiny3d::error{o.out_dir, 0, -1, "cannot create the output folder: " + ec.message()};
    return {};
}

std::string frame_path(const common_options &o, int frame, const std::string &prefix) {
    char num[32];
    std::snprintf(num, sizeof num, "%03d", frame);
    return o.out_dir + "/" + prefix + num + ".pgm";
}

progress::progress(std::string name, int total)
    : name_(std::move(name)), total_(total), terminal_(::isatty(STDOUT_FILENO) == 1),
      began_s_(tiny3d::frame_clock::steady_seconds()) {
    clock_.reserve(std::size_t(std::max(total, 0)));
}

progress::progress(std::string name, const common_options &o) : progress(std::move(name), o.frames_to_render()) {
    write_frames_ = o.write_frames();
    gif_path_ = o.gif_path;
    gif_options_.fps = o.fps;
}

void progress::start() { frame_began_s_ = tiny3d::frame_clock::steady_seconds(); }

void progress::stop() {
    // A steady clock never runs backwards, so the difference is a valid frame time.
    (void)clock_.add_frame(tiny3d::frame_clock::steady_seconds() - frame_began_s_);
}

void progress::report_written(const std::string &path) {
    if (!terminal_) {
        std::printf("wrote %s\n", path.c_str());
        return;
    }
    // \033[K clears the rest of the line left by a longer previous one.
    std::printf("\r%s: frame %zu/%d  %.2f ms (%.1f fps over the last %zu)  wrote %s\033[K", name_.c_str(),
                clock_.frame_count(), total_, 1000.0 * clock_.last_frame_seconds(), clock_.rolling_fps(),
                std::min(clock_.frame_count(), clock_.window()), path.c_str());
    std::fflush(stdout);
    line_open_ = true;
}

tiny3d::status progress::save(const canvas_t &canvas, const std::string &pgm_path, bool png) {
    if (!gif_path_.empty()) {
        if (!gif_) {
            auto writer = tiny3d::gif_writer::create(gif_path_, canvas.width, canvas.height, gif_options_);
            if (!writer) return writer.to_status();
            gif_.emplace(std::move(*writer));
        }
        if (tiny3d::status s = gif_->add_frame(canvas); !s) return s;
    }
    if (!write_frames_) return {};
    if (tiny3d::status s = tiny3d::save_pgm(canvas, pgm_path); !s) return s;
    report_written(pgm_path);
    if (!png) return {};
    std::string png_path = pgm_path;
    if (png_path.size() > 4 && png_path.compare(png_path.size() - 4, 4, ".pgm") == 0) png_path.resize(png_path.size() - 4);
    png_path += ".png";
    if (tiny3d::status s = tiny3d::save_png(canvas, png_path); !s) return s;
    report_written(png_path);
    return {};
}

tiny3d::status progress::finish() {
    tiny3d::status gif_status;
    if (gif_) {
        gif_status = gif_->finish();
        if (gif_status) report_written(gif_path_);
        gif_.reset();
    }
    if (line_open_) std::printf("\n");
    std::fflush(stdout);
    line_open_ = false;
    const tiny3d::frame_summary s = clock_.summary();
    if (!gif_status || s.frames == 0) return gif_status;
    using tiny3d::frame_clock;
    const double total = frame_clock::steady_seconds() - began_s_;
    std::fprintf(stderr,
                 "%s: %zu frame%s in %.2f s (with saving); render ms per frame min %.2f / median %.2f / max %.2f "
                 "(%.1f / %.1f / %.1f fps)\n",
                 name_.c_str(), s.frames, s.frames == 1 ? "" : "s", total, 1000.0 * s.min_s, 1000.0 * s.median_s,
                 1000.0 * s.max_s, frame_clock::fps(s.min_s), frame_clock::fps(s.median_s), frame_clock::fps(s.max_s));
    return {};
}

tiny3d::line_method line_method_named(const std::string &name) {
    if (name == "tabulated") return tiny3d::line_method::tabulated;
    if (name == "faithful") return tiny3d::line_method::faithful;
    return tiny3d::line_method::coverage;
}

}  // namespace demo
