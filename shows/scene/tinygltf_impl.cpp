// tinygltf's implementation, compiled into haze from Debian's header instead of linked from
// libtinygltf.so: libdraco (which assimp pulls in) exports its own, differently built copy of
// tinygltf's symbols, and whichever shared library loads first wins. Symbols of our own
// executable always come first, so this copy is the one every haze call reaches.
// stb_image comes from libstb (Debian), so only its declarations are included here.
#include <stb_image.h>
#include <stb_image_write.h>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE_WRITE
#include <tiny_gltf.h>
