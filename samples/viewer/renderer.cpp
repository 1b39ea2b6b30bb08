#include "renderer.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

const char* kMeshVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model_view;
uniform mat4 projection;
out vec3 eye_normal;
void main() {
  eye_normal = mat3(model_view) * normal;
  gl_Position = projection * model_view * vec4(position, 1.0);
})";

const char* kMeshFragment = R"(#version 330 core
in vec3 eye_normal;
uniform vec3 colour;
out vec4 fragment;
void main() {
  // Head light plus a fill from above: every side of the body stays readable.
  vec3 n = normalize(eye_normal);
  float key = abs(n.z);
  float fill = 0.5 + 0.5 * n.y;
  fragment = vec4(colour * (0.25 + 0.6 * key + 0.25 * fill), 1.0);
})";

const char* kLineVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour_in;
uniform mat4 view_projection;
out vec3 colour;
void main() {
  colour = colour_in;
  gl_Position = view_projection * vec4(position, 1.0);
})";

const char* kLineFragment = R"(#version 330 core
in vec3 colour;
out vec4 fragment;
void main() { fragment = vec4(colour, 1.0); })";

unsigned compile(const GlApi& gl, unsigned kind, const char* source) {
  const unsigned s = gl.CreateShader(kind);
  gl.ShaderSource(s, 1, &source, nullptr);
  gl.CompileShader(s);
  int ok = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader compilation failed: ") + log);
  }
  return s;
}

unsigned program(const GlApi& gl, const char* vertex, const char* fragment) {
  const unsigned v = compile(gl, GL_VERTEX_SHADER, vertex), f = compile(gl, GL_FRAGMENT_SHADER, fragment);
  const unsigned p = gl.CreateProgram();
  gl.AttachShader(p, v);
  gl.AttachShader(p, f);
  gl.LinkProgram(p);
  gl.DeleteShader(v);
  gl.DeleteShader(f);
  int ok = 0;
  gl.GetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    gl.GetProgramInfoLog(p, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader link failed: ") + log);
  }
  return p;
}

Eigen::Matrix4f perspective_from_k(double fx, double fy, double cx, double cy, int w, int h, double n, double f) {
  Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
  p(0, 0) = static_cast<float>(2 * fx / w);
  p(0, 2) = static_cast<float>(1 - 2 * cx / w);
  p(1, 1) = static_cast<float>(2 * fy / h);
  p(1, 2) = static_cast<float>(2 * cy / h - 1);
  p(2, 2) = static_cast<float>(-(f + n) / (f - n));
  p(2, 3) = static_cast<float>(-2 * f * n / (f - n));
  p(3, 2) = -1;
  return p;
}

}  // namespace

ViewCamera calibrated_camera(const Eigen::Matrix3d& K, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                             const Eigen::Matrix3d& rig_to_world, int width, int height) {
  ViewCamera c;
  c.width = width;
  c.height = height;
  // OpenCV camera (x right, y down, z forward) -> GL eye (x right, y up, z backward).
  Eigen::Matrix4d cv = Eigen::Matrix4d::Identity();
  cv.topLeftCorner<3, 3>() = R * rig_to_world;
  cv.topRightCorner<3, 1>() = t;
  const Eigen::Matrix4d flip = Eigen::Vector4d(1, -1, -1, 1).asDiagonal();
  c.view = (flip * cv).cast<float>();
  c.projection = perspective_from_k(K(0, 0), K(1, 1), K(0, 2), K(1, 2), width, height, 0.05, 100.0);
  return c;
}

ViewCamera orbit_camera(const Eigen::Vector3f& target, float distance, float yaw, float pitch, float fov_deg,
                        int width, int height) {
  const Eigen::Vector3f eye = target + distance * Eigen::Vector3f(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                                                  std::cos(yaw) * std::cos(pitch));
  const Eigen::Vector3f back = (eye - target).normalized();
  const Eigen::Vector3f right = Eigen::Vector3f::UnitY().cross(back).normalized();
  const Eigen::Vector3f up = back.cross(right);
  ViewCamera c;
  c.width = width;
  c.height = height;
  c.view.topLeftCorner<3, 3>() << right.transpose(), up.transpose(), back.transpose();
  c.view.topRightCorner<3, 1>() = -c.view.topLeftCorner<3, 3>() * eye;
  const double f = 0.5 * height / std::tan(fov_deg * M_PI / 360.0);
  c.projection = perspective_from_k(f, f, 0.5 * width, 0.5 * height, width, height, 0.05, 100.0);
  return c;
}

Renderer::Renderer(const GlApi& gl, const std::vector<const SkinnedMesh*>& meshes) : gl_(gl) {
  mesh_program_ = program(gl, kMeshVertex, kMeshFragment);
  line_program_ = program(gl, kLineVertex, kLineFragment);
  for (const SkinnedMesh* m : meshes) {
    unsigned vao = 0, vbo = 0, ebo = 0;
    gl.GenVertexArrays(1, &vao);
    gl.GenBuffers(1, &vbo);
    gl.GenBuffers(1, &ebo);
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m->positions.size() * 6 * sizeof(float)), nullptr, GL_STREAM_DRAW);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0,
                           reinterpret_cast<const void*>(m->positions.size() * 3 * sizeof(float)));
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m->indices.size() * sizeof(uint32_t)),
                  m->indices.data(), GL_STATIC_DRAW);
    vaos_.push_back(vao);
    vbos_.push_back(vbo);
    ebos_.push_back(ebo);
    index_counts_.push_back(m->indices.size());
  }
  gl.GenVertexArrays(1, &line_vao_);
  gl.GenBuffers(1, &line_vbo_);
  gl.BindVertexArray(line_vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo_);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
  gl.BindVertexArray(0);
}

Renderer::~Renderer() {
  gl_.DeleteBuffers(static_cast<int>(vbos_.size()), vbos_.data());
  gl_.DeleteBuffers(static_cast<int>(ebos_.size()), ebos_.data());
  gl_.DeleteVertexArrays(static_cast<int>(vaos_.size()), vaos_.data());
  gl_.DeleteBuffers(1, &line_vbo_);
  gl_.DeleteVertexArrays(1, &line_vao_);
  gl_.DeleteProgram(mesh_program_);
  gl_.DeleteProgram(line_program_);
}

void Renderer::upload_lines(const std::vector<float>& v) {
  gl_.BindVertexArray(line_vao_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, line_vbo_);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STREAM_DRAW);
  gl_.DrawArrays(GL_LINES, 0, static_cast<int>(v.size() / 6));
}

void Renderer::draw(const ViewCamera& camera, const std::vector<SkinnedVertices>& meshes,
                    const Eigen::Affine3f& model_to_world, const std::vector<Segment>& skeleton, bool grid,
                    float floor_y) {
  draw(camera, std::vector<Drawable>{Drawable{&meshes, model_to_world}}, skeleton, grid, floor_y);
}

void Renderer::draw(const ViewCamera& camera, const std::vector<Drawable>& characters,
                    const std::vector<Segment>& skeleton, bool grid, float floor_y) {
  gl_.Viewport(0, 0, camera.width, camera.height);
  gl_.ClearColor(0.93f, 0.94f, 0.96f, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  const Eigen::Matrix4f view_projection = camera.projection * camera.view;

  if (grid) {
    std::vector<float> lines;
    for (int i = -6; i <= 6; ++i) {
      const float a = 0.5f * static_cast<float>(i), colour = i == 0 ? 0.45f : 0.7f;
      for (const auto& [p, q] : {std::pair<Eigen::Vector3f, Eigen::Vector3f>{{a, floor_y, -3}, {a, floor_y, 3}},
                                 std::pair<Eigen::Vector3f, Eigen::Vector3f>{{-3, floor_y, a}, {3, floor_y, a}}})
        lines.insert(lines.end(), {p.x(), p.y(), p.z(), colour, colour, colour, q.x(), q.y(), q.z(), colour, colour, colour});
    }
    gl_.UseProgram(line_program_);
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(line_program_, "view_projection"), 1, GL_FALSE, view_projection.data());
    upload_lines(lines);
  }

  // The first character keeps the single-character colour; the others are told apart by theirs.
  static const float kColours[][3] = {{0.85f, 0.62f, 0.45f}, {0.45f, 0.62f, 0.85f}, {0.55f, 0.80f, 0.50f},
                                      {0.85f, 0.50f, 0.70f}, {0.80f, 0.78f, 0.40f}, {0.55f, 0.50f, 0.85f}};
  gl_.UseProgram(mesh_program_);
  gl_.UniformMatrix4fv(gl_.GetUniformLocation(mesh_program_, "projection"), 1, GL_FALSE, camera.projection.data());
  for (size_t c = 0; c < characters.size(); ++c) {
    if (!characters[c].meshes) continue;
    const std::vector<SkinnedVertices>& meshes = *characters[c].meshes;
    const Eigen::Matrix4f model_view = camera.view * characters[c].model_to_world.matrix();
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(mesh_program_, "model_view"), 1, GL_FALSE, model_view.data());
    gl_.Uniform3fv(gl_.GetUniformLocation(mesh_program_, "colour"), 1, kColours[c % 6]);
    for (size_t m = 0; m < meshes.size() && m < vaos_.size(); ++m) {
      const size_t n = meshes[m].positions.size();
      gl_.BindVertexArray(vaos_[m]);
      gl_.BindBuffer(GL_ARRAY_BUFFER, vbos_[m]);
      gl_.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(n * 3 * sizeof(float)), meshes[m].positions.data());
      gl_.BufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(n * 3 * sizeof(float)),
                        static_cast<GLsizeiptr>(n * 3 * sizeof(float)), meshes[m].normals.data());
      gl_.DrawElements(GL_TRIANGLES, static_cast<int>(index_counts_[m]), GL_UNSIGNED_INT, nullptr);
    }
  }

  if (!skeleton.empty()) {
    gl_.Disable(GL_DEPTH_TEST);  // the overlay shows through the body
    std::vector<float> lines;
    for (const auto& [a, b] : skeleton)
      lines.insert(lines.end(), {a.x(), a.y(), a.z(), 0.1f, 0.3f, 0.9f, b.x(), b.y(), b.z(), 0.1f, 0.3f, 0.9f});
    gl_.UseProgram(line_program_);
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(line_program_, "view_projection"), 1, GL_FALSE, view_projection.data());
    gl_.LineWidth(1.0f);
    upload_lines(lines);
  }
  gl_.BindVertexArray(0);
}
