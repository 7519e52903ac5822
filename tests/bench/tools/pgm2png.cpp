// pgm2png.cpp — converts PGM images to PNG with the library's own reader and writer.
//   pgm2png IN.pgm OUT.png [IN2.pgm OUT2.png ...]     (make docs-charts)
#include <cstdio>

#include "canvas.h"

int main(int argc, char **argv) {
    if (argc < 3 || argc % 2 == 0) {
        std::fprintf(stderr, "usage: %s IN.pgm OUT.png [IN.pgm OUT.png ...]\n", argv[0]);
        return 2;
    }
    for (int i = 1; i + 1 < argc; i += 2) {
        const auto canvas = tiny3d::load_pgm(argv[i]);
        if (!canvas) {
            std::fprintf(stderr, "pgm2png: %s\n", canvas.message().c_str());
            return 1;
        }
        if (const tiny3d::status s = tiny3d::save_png(**canvas, argv[i + 1]); !s) {
            std::fprintf(stderr, "pgm2png: %s\n", s.message().c_str());
            return 1;
        }
        std::printf("wrote %s\n", argv[i + 1]);
    }
    return 0;
}
