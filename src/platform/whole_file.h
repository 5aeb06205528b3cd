#pragma once
// A file written whole or not at all: the bytes go beside it (path + ".part") and are moved
// over it once closed without error. A full disk had left truncated PNGs, saved scenes and
// window settings that were called written. Header only: the scenes, the renderer and the
// window use it without linking the platform's GL.
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace platform {

// Whether `path` now holds `bytes`; if not, it is as it was, and no .part is left.
inline bool writeWholeFile(const std::string& path, const std::string& bytes) {
    const std::string part = path + ".part";
    std::ofstream file(part, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), std::streamsize(bytes.size()));
    file.close();
    std::error_code error;
    if (file) std::filesystem::rename(part, path, error);
    const bool written = file && !error;
    if (!written) std::filesystem::remove(part, error);
    return written;
}

}  // namespace platform
