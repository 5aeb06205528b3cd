#pragma once
// Internal to spheres_platform: one factory per compiled headless backend.
#include <memory>
#include <string>

#include "platform/headless_context.h"

namespace platform::detail {

std::unique_ptr<HeadlessContext> createOsMesaContext(std::string* error);
std::unique_ptr<HeadlessContext> createEglContext(std::string* error);

}  // namespace platform::detail
