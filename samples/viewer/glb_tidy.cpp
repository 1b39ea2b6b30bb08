#include "glb_tidy.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <vector>

using nlohmann::json;

namespace {

constexpr uint32_t kMagic = 0x46546C67, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;
constexpr int kFloat = 5126, kArrayBuffer = 34962, kElementArrayBuffer = 34963;

uint32_t read_u32(const std::vector<char>& b, size_t at) {
  if (at + 4 > b.size()) throw std::runtime_error("the .glb ends inside a chunk header");
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

void put_u32(std::vector<char>& b, uint32_t v) {
  const char* p = reinterpret_cast<const char*>(&v);
  b.insert(b.end(), p, p + 4);
}

void drop_extension(json& owner, const char* name) {
  if (!owner.contains("extensions")) return;
  owner["extensions"].erase(name);
  if (owner["extensions"].empty()) owner.erase("extensions");
}

void drop_used(json& gltf, const char* name) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    if (!gltf.contains(list)) continue;
    json& l = gltf[list];
    l.erase(std::remove(l.begin(), l.end(), json(name)), l.end());
    if (l.empty()) gltf.erase(list);
  }
}

// The core material keeps what the specular-glossiness one said of colour: diffuse becomes base colour, a surface
// neither metal nor glossy stays so.
void to_metallic_roughness(json& material) {
  if (!material.contains("extensions") || !material["extensions"].contains("KHR_materials_pbrSpecularGlossiness"))
    return;
  const json sg = material["extensions"]["KHR_materials_pbrSpecularGlossiness"];
  json& mr = material["pbrMetallicRoughness"];
  if (sg.contains("diffuseFactor") && !mr.contains("baseColorFactor")) mr["baseColorFactor"] = sg["diffuseFactor"];
  if (sg.contains("diffuseTexture") && !mr.contains("baseColorTexture")) mr["baseColorTexture"] = sg["diffuseTexture"];
  if (!mr.contains("metallicFactor")) mr["metallicFactor"] = 0.0;
  if (!mr.contains("roughnessFactor")) mr["roughnessFactor"] = 1.0 - sg.value("glossinessFactor", 1.0);
  drop_extension(material, "KHR_materials_pbrSpecularGlossiness");
}

// Each vertex's four weights divided by their sum, the largest then set to what makes the sum of the four floats
// 1 as closely as a float can (the validator allows a few 1e-7, dividing alone misses by up to 1e-6).
void normalise_weights(json& gltf, size_t accessor_index, std::vector<char>& bin) {
  json& accessor = gltf["accessors"][accessor_index];
  if (accessor.value("componentType", 0) != kFloat || accessor.value("type", "") != "VEC4" ||
      !accessor.contains("bufferView"))
    return;  // normalised integer weights: assimp writes floats
  const json& view = gltf["bufferViews"][accessor["bufferView"].get<size_t>()];
  const size_t stride = view.value("byteStride", size_t{16}), count = accessor["count"].get<size_t>();
  const size_t start = view.value("byteOffset", size_t{0}) + accessor.value("byteOffset", size_t{0});
  if (count == 0) return;
  if (start + (count - 1) * stride + 16 > bin.size()) throw std::runtime_error("a weights accessor runs past the buffer");
  std::vector<float> lo(4, 1.0f), hi(4, 0.0f);
  for (size_t i = 0; i < count; ++i) {
    float w[4];
    std::memcpy(w, bin.data() + start + i * stride, sizeof w);
    double sum = 0;
    for (float x : w) sum += x;
    if (sum > 0) {
      for (float& x : w) x = static_cast<float>(x / sum);
      const size_t big = static_cast<size_t>(std::max_element(w, w + 4) - w);
      double others = 0;
      for (size_t k = 0; k < 4; ++k) others += k == big ? 0.0 : static_cast<double>(w[k]);
      w[big] = static_cast<float>(1.0 - others);
    }
    std::memcpy(bin.data() + start + i * stride, w, sizeof w);
    for (size_t k = 0; k < 4; ++k) lo[k] = std::min(lo[k], w[k]), hi[k] = std::max(hi[k], w[k]);
  }
  // Its bounds follow (the validator checks them against the data).
  if (accessor.contains("min")) accessor["min"] = lo;
  if (accessor.contains("max")) accessor["max"] = hi;
}

// A skinned mesh is placed by its joints alone: its node goes to the scene's root, without a transform of its own.
void skinned_meshes_to_root(json& gltf) {
  json& nodes = gltf["nodes"];
  std::set<size_t> skinned;
  for (size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].contains("skin") && nodes[i].contains("mesh")) skinned.insert(i);
  if (skinned.empty()) return;
  for (json& n : nodes) {
    if (!n.contains("children")) continue;
    json& c = n["children"];
    c.erase(std::remove_if(c.begin(), c.end(), [&](const json& i) { return skinned.count(i.get<size_t>()) > 0; }),
            c.end());
    if (c.empty()) n.erase("children");
  }
  for (size_t i : skinned)
    for (const char* t : {"translation", "rotation", "scale", "matrix"}) nodes[i].erase(t);
  json& scene = gltf["scenes"][gltf.value("scene", size_t{0})]["nodes"];
  for (size_t i : skinned)
    if (std::find(scene.begin(), scene.end(), json(i)) == scene.end()) scene.push_back(i);
}

// Buffer views only vertex attributes (or only indices) read say so, as GPUs upload them.
void set_view_targets(json& gltf) {
  std::set<size_t> vertex, index, other;
  auto view_of = [&](const json& accessor_index) -> long {
    const json& a = gltf["accessors"][accessor_index.get<size_t>()];
    return a.contains("bufferView") ? a["bufferView"].get<long>() : -1;
  };
  std::set<size_t> vertex_or_index_accessors;
  for (const json& mesh : gltf.value("meshes", json::array()))
    for (const json& p : mesh["primitives"]) {
      for (const auto& [name, acc] : p["attributes"].items()) {
        vertex_or_index_accessors.insert(acc.get<size_t>());
        if (view_of(acc) >= 0) vertex.insert(static_cast<size_t>(view_of(acc)));
      }
      if (p.contains("indices")) {
        vertex_or_index_accessors.insert(p["indices"].get<size_t>());
        if (view_of(p["indices"]) >= 0) index.insert(static_cast<size_t>(view_of(p["indices"])));
      }
    }
  for (size_t a = 0; a < gltf["accessors"].size(); ++a)
    if (!vertex_or_index_accessors.count(a) && gltf["accessors"][a].contains("bufferView"))
      other.insert(gltf["accessors"][a]["bufferView"].get<size_t>());
  json& views = gltf["bufferViews"];
  for (size_t v = 0; v < views.size(); ++v) {
    if (views[v].contains("target") || other.count(v) || (vertex.count(v) && index.count(v))) continue;
    if (vertex.count(v)) views[v]["target"] = kArrayBuffer;
    if (index.count(v)) views[v]["target"] = kElementArrayBuffer;
  }
}

}  // namespace

void tidy_glb(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (file.size() < 20 || read_u32(file, 0) != kMagic || read_u32(file, 4) != 2)
    throw std::runtime_error(path + " is not a glTF 2.0 binary");
  const uint32_t json_length = read_u32(file, 12);
  if (read_u32(file, 16) != kJsonChunk || 20 + size_t{json_length} > file.size())
    throw std::runtime_error(path + ": its first chunk is not its JSON");
  json gltf = json::parse(file.begin() + 20, file.begin() + 20 + json_length);
  std::vector<char> bin;
  const size_t bin_at = 20 + size_t{json_length};
  if (bin_at + 8 <= file.size()) {
    const uint32_t bin_length = read_u32(file, bin_at);
    if (read_u32(file, bin_at + 4) != kBinChunk || bin_at + 8 + bin_length > file.size())
      throw std::runtime_error(path + ": its second chunk is not its buffer");
    bin.assign(file.begin() + static_cast<std::ptrdiff_t>(bin_at + 8),
               file.begin() + static_cast<std::ptrdiff_t>(bin_at + 8 + bin_length));
  }

  if (gltf.contains("materials"))
    for (json& m : gltf["materials"]) to_metallic_roughness(m);
  drop_used(gltf, "KHR_materials_pbrSpecularGlossiness");
  if (gltf.contains("meshes"))
    for (json& mesh : gltf["meshes"])
      for (json& p : mesh["primitives"]) {
        drop_extension(p, "FB_ngon_encoding");
        for (const auto& [name, acc] : p["attributes"].items())
          if (name.rfind("WEIGHTS_", 0) == 0) normalise_weights(gltf, acc.get<size_t>(), bin);
      }
  drop_used(gltf, "FB_ngon_encoding");
  if (gltf.contains("nodes") && gltf.contains("scenes")) skinned_meshes_to_root(gltf);
  if (gltf.contains("bufferViews") && gltf.contains("accessors")) set_view_targets(gltf);

  std::string text = gltf.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned: JSON pads with spaces, the buffer zeros
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  std::vector<char> out;
  put_u32(out, kMagic);
  put_u32(out, 2);
  put_u32(out, static_cast<uint32_t>(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size())));
  put_u32(out, static_cast<uint32_t>(text.size()));
  put_u32(out, kJsonChunk);
  out.insert(out.end(), text.begin(), text.end());
  if (!bin.empty()) {
    put_u32(out, static_cast<uint32_t>(bin.size()));
    put_u32(out, kBinChunk);
    out.insert(out.end(), bin.begin(), bin.end());
  }
  std::ofstream o(path, std::ios::binary | std::ios::trunc);
  o.write(out.data(), static_cast<std::streamsize>(out.size()));
  if (!o) throw std::runtime_error("cannot write " + path);
}
