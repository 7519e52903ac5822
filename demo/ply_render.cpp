// ply_render — the PLY ray-cast lab (seed 002):
//   ply_render FILE.ply RX RY RZ [OUT] [--method raycast|fast]
// Angles in degrees (rotation about X, then Y, then Z). Writes a 256×256 grey image: P6 PPM,
// or P5 PGM when OUT ends in .pgm; default OUT = the PLY's name with .ppm, in the current
// folder. --method raycast is the lab's per-pixel loop over every triangle; the default
// (fast) runs the same per-pixel test only inside each triangle's projected box and gives
// the identical image. Prints "wrote OUT" on stdout and the time on stderr; usage, loader
// and write errors go to stderr with exit status 1.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "loaders.h"
#include "renderer.h"

namespace {

constexpr const char *USAGE = "usage: ply_render FILE.ply RX RY RZ [OUT] [--method raycast|fast]  (angles in degrees)";

int fail(const std::string &message) {
    std::fprintf(stderr, "ply_render: %s\n", message.c_str());
    return 1;
}

bool parse_degrees(const std::string &text, double &radians) {
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v)) return false;
    radians = v * M_PI / 180.0;
    return true;
}

std::string default_output(const std::string &input) {
    std::string name = input.substr(input.find_last_of('/') + 1);
    const std::size_t dot = name.find_last_of('.');
    if (dot != std::string::npos && dot > 0) name = name.substr(0, dot);
    return name + ".ppm";
}

}  // namespace

int main(int argc, char **argv) {
    std::vector<std::string> args;
    std::string method = "fast";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--method") {
            if (i + 1 >= argc) return fail(std::string("--method needs a value\n") + USAGE);
            method = argv[++i];
        } else if (a.rfind("--method=", 0) == 0) {
            method = a.substr(9);
        } else if (a == "--help" || a == "-h") {
            std::printf("%s\n", USAGE);
            return 0;
        } else {
            args.push_back(a);
        }
    }
    if (method != "fast" && method != "raycast") return fail("unknown method '" + method + "'\n" + USAGE);
    if (args.size() < 4 || args.size() > 5) return fail(USAGE);
    double angle[3];
    for (int k = 0; k < 3; ++k)
        if (!parse_degrees(args[1 + k], angle[k])) return fail("'" + args[1 + k] + "' is not an angle in degrees\n" + USAGE);
    const std::string out = args.size() == 5 ? args[4] : default_output(args[0]);

    const auto t0 = std::chrono::steady_clock::now();
    tiny3d::result<tiny3d::mesh> mesh = tiny3d::load_ply(args[0]);
    if (!mesh) return fail(mesh.message());
    tiny3d::result<tiny3d::lab_camera> cam = tiny3d::ply_lab_camera(*mesh, angle[0], angle[1], angle[2]);
    if (!cam) return fail(args[0] + ": " + cam.message());
    const tiny3d::lab_image img =
        method == "raycast" ? tiny3d::raycast_lab(*mesh, *cam) : tiny3d::render_lab_fast(*mesh, *cam);
    const auto t1 = std::chrono::steady_clock::now();
    const tiny3d::status saved = tiny3d::save_lab_image(img, out);
    if (!saved) return fail(saved.message());
    std::fprintf(stderr, "ply_render: %zu faces, %s, %.2f ms (read + render)\n", mesh->face_count(), method.c_str(),
                 std::chrono::duration<double, std::milli>(t1 - t0).count());
    std::printf("wrote %s\n", out.c_str());
    return 0;
}
