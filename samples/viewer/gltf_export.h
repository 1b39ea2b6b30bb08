// Exports the character with the motion baked in as a glTF 2.0 binary (GLB): the model's own meshes, skin and
// hierarchy, plus one animation whose channels are the retargeted bones (rotations) and the placement of the
// scene root (position, orientation, scale), one key per motion frame. Any engine or DCC tool imports it.
#pragma once
#include <string>

class Scene;

// Throws std::runtime_error with assimp's message.
void export_gltf(Scene& scene, const std::string& model_path, const std::string& out_path, int first_frame,
                 int frame_count, int step);
