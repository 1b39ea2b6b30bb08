// What assimp's glTF 2.0 exporter writes and the Khronos glTF-Validator refuses or warns about, put right in the
// written .glb: joint weights whose float sum misses 1 by an ulp or two (an error), skinned meshes on nodes with
// parents and transforms (the spec ignores both; the validator warns that readers may not), the archived
// KHR_materials_pbrSpecularGlossiness material (its colour is carried over to the core metallic-roughness one) and
// Facebook's FB_ngon_encoding, and vertex buffer views without their target.
#pragma once
#include <string>

// Rewrites the .glb at `path` in place; throws std::runtime_error on a file that is not one.
void tidy_glb(const std::string& path);
