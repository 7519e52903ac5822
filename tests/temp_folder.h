// tests/temp_folder.h — a private temporary folder for a test, removed (with the files
// the test made through it) at the end.
#ifndef TINY3D_TEST_TEMP_FOLDER_H
#define TINY3D_TEST_TEMP_FOLDER_H

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

struct temp_folder {
    std::string path;
    std::vector<std::string> files;
    temp_folder() {
        char name[] = "/tmp/tiny3d_test_XXXXXX";
        path = ::mkdtemp(name) ? name : "/tmp";
    }
    // Writes `bytes` to the folder's file `leaf` and returns its path.
    std::string file(const std::string &leaf, const std::string &bytes) {
        const std::string p = named(leaf);
        if (std::FILE *f = std::fopen(p.c_str(), "wb")) {
            std::fwrite(bytes.data(), 1, bytes.size(), f);
            std::fclose(f);
        }
        return p;
    }
    // The path of `leaf` in the folder, removed at the end (whatever the test makes there).
    std::string named(const std::string &leaf) {
        files.push_back(path + "/" + leaf);
        return files.back();
    }
    ~temp_folder() {
        for (const std::string &f : files) std::remove(f.c_str());
        ::rmdir(path.c_str());
    }
};

#endif
