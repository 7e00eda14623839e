// A glTF venue (.gltf with its .bin files and images, or .glb) as one binary glTF (.glb), the
// form MVR embeds geometry in: buffers and images are packed into the GLB's binary chunk.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "fixtures/core/result.h"

namespace haze {

// The .glb bytes; a .glb is returned as it is. Errors name the file (a missing buffer or image,
// JSON that does not parse, more than 512 MB in all).
Result<std::vector<std::uint8_t>> packGlb(const std::filesystem::path& gltfFile);

}  // namespace haze
