// fxport_content: generates the assets of the deferred-renderer demo (seed 000) into a folder.
//   fxport_content <output-dir>
// Everything is procedural with fixed seeds: two runs write byte-identical files.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "image.h"
#include "light_geometry.h"
#include "light_textures.h"
#include "scene.h"

int main(int argc, char** argv) {
    namespace content = fxport::content;
    if (argc != 2) {
        std::fprintf(stderr, "usage: fxport_content <output-dir>\n");
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        content::WriteScene(dir);
        content::WritePointLightGeometry(dir);
        content::WriteSpotLightGeometry(dir);
        content::WritePng(content::MakeSpotCookie(256), dir / "SpotCookie.png");
        content::WritePng(content::MakeSquareCookie(256), dir / "SquareCookie.png");
        content::WritePng(content::MakeRandomNormals(64, 0x52616e644e726d73ULL), dir / "RandomNormals.png");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fxport_content: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
