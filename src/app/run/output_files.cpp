#include "app/run/output_files.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace app {
namespace fs = std::filesystem;

namespace {
constexpr int kMostFiles = 9999;  // of one kind in the folder
}  // namespace

std::string outputFolder() {
    std::error_code error;
    const fs::path here = fs::current_path(error);
    return ((error ? fs::path(".") : here) / "spheres_output").string();
}

std::string freshPath(const std::string& folder, const std::string& stem, const std::string& extension,
                      std::string& error) {
    std::error_code code;
    fs::create_directories(folder, code);
    if (code || !fs::is_directory(folder, code)) {
        error = "cannot create the folder " + folder + (code ? ": " + code.message() : "");
        return "";
    }
    for (int n = 1; n <= kMostFiles; ++n) {
        char name[64];
        std::snprintf(name, sizeof name, "_%04d.", n);
        const fs::path path = fs::path(folder) / (stem + name + extension);
        if (!fs::exists(path, code)) return path.string();
    }
    error = folder + " already holds " + std::to_string(kMostFiles) + " " + stem + " files: move some away";
    return "";
}

}  // namespace app
