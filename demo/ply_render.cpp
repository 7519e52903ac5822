// ply_render — the PLY ray-cast program (the lab exercise it reproduces: a ray per pixel,
// z-buffer):
//   ply_render FILE.ply RX RY RZ [OUT] [--method raycast|fast] [--size NxN]
// Angles in degrees (rotation about X, then Y, then Z). Writes a 256×256 grey image (the
// lab's size; --size changes it, square only): P6 PPM, or P5 PGM when OUT ends in .pgm;
// default OUT = the PLY's name with .ppm, in the current folder. --method raycast is the
// lab's per-pixel loop over every triangle; the default (fast) runs the same per-pixel test
// only inside each triangle's projected box and gives the identical image. Prints "wrote
// OUT" on stdout and the time on stderr. Exit status 2 for a bad command line (nothing
// written), 1 for a file that does not load or an image that cannot be saved.
#include <algorithm>
#include <cmath>
#include <string>

#include "common/demo_cli.h"
#include "lab.h"
#include "mesh.h"

namespace {

std::string default_output(const std::string &input) {
    std::string name = input.substr(input.find_last_of('/') + 1);
    const std::size_t dot = name.find_last_of('.');
    if (dot != std::string::npos && dot > 0) name = name.substr(0, dot);
    return name + ".ppm";
}

}  // namespace

int main(int argc, char **argv) {
    demo::command_line cli("ply_render", "FILE.ply RX RY RZ [OUT]",
                           "The PLY ray-cast lab: the mesh seen by the lab's camera after rotating it RX, RY, RZ\n"
                           "degrees about X, then Y, then Z; each pixel's grey is 155 + (i mod 100) for the nearest\n"
                           "triangle i along its ray, 0 where no triangle is hit. OUT is P6 PPM, or P5 PGM when it\n"
                           "ends in .pgm (default: the PLY's name with .ppm, in the current folder).");
    std::string path, angle_text[3], out, method = "fast";
    cli.positional("FILE.ply", path, true);
    cli.positional("RX", angle_text[0], true);
    cli.positional("RY", angle_text[1], true);
    cli.positional("RZ", angle_text[2], true);
    cli.positional("OUT", out, false);
    cli.choice("--method", method, {"fast", "raycast"},
               "raycast: every triangle per pixel, as the lab; fast (default): the same test inside "
               "each triangle's projected box, the identical image");
    cli.add_size(tiny3d::LAB_IMAGE_SIDE, tiny3d::LAB_IMAGE_SIDE);  // square only: checked below
    if (const int status = cli.parse(argc, argv); status >= 0) return status;
    double angle[3];
    const char *names[3] = {"RX", "RY", "RZ"};
    for (int k = 0; k < 3; ++k) {
        if (std::string e = demo::parse_number(names[k], angle_text[k], -1e6, 1e6, angle[k]); !e.empty())
            return cli.usage_error(e + " (degrees)");
        angle[k] *= M_PI / 180.0;
    }
    if (cli.common.width != cli.common.height)
        return cli.usage_error("--size wants a square NxN (the lab's image is square), got '" +
                               std::to_string(cli.common.width) + "x" + std::to_string(cli.common.height) + "'");
    if (out.empty()) out = default_output(path);

    demo::progress timer("ply_render", 1);
    timer.start();
    tiny3d::result<tiny3d::mesh> mesh = tiny3d::load_ply(path);
    if (!mesh) return cli.fail(mesh.message());
    tiny3d::result<tiny3d::lab_camera> cam = tiny3d::ply_lab_camera(*mesh, angle[0], angle[1], angle[2]);
    if (!cam) return cli.fail(path + ": " + cam.message());
    const int side = cli.common.width;
    const tiny3d::lab_image img =
        method == "raycast" ? tiny3d::raycast_lab(*mesh, *cam, side) : tiny3d::render_lab_fast(*mesh, *cam, side);
    timer.stop();
    // The camera frames the mesh, so a blank image means every face is edge-on or degenerate.
    if (std::find_if(img.pixels.begin(), img.pixels.end(), [](std::uint8_t v) { return v != 0; }) == img.pixels.end())
        std::fprintf(stderr, "ply_render: warning: %s: the image is blank (no face is seen)\n", path.c_str());
    if (const tiny3d::status saved = tiny3d::save_lab_image(img, out); !saved) return cli.fail(saved.message());
    timer.report_written(out);
    std::fprintf(stderr, "ply_render: %zu faces, %s method\n", mesh->face_count(), method.c_str());
    timer.finish();
    return 0;
}

