#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "render/error.hpp"
#include "render/gl_program.hpp"
#include "render/object_meshes.hpp"
#include "render/shaders.hpp"
#include "render/terrain_mesh.hpp"

namespace vbim::render {

namespace {

std::string fragment(const char* body) {
  return std::string("#version 330 core\n") + shaders::kCommon + body;
}

void textureParams(GLint wrapS, GLint wrapT) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrapS);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrapT);
}

// 8-bit sRGB-coded RGBA8 -> an sRGB texture (GL decodes to linear when sampling).
void uploadSrgb(GLuint tex, const Rgba8Image& img) {
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               img.pixels.data());
}

}  // namespace

struct Renderer::Gl {
  // The GL objects below are deleted in this context.
  ~Gl() {
    if (context) context->makeCurrent();
  }
  std::unique_ptr<GlContext> context;
  int width = 0, height = 0;
  RenderSettings settings;
  CameraPlacement camera;
  const lighting::Terrain* terrain = nullptr;
  TerrainMesh mesh;
  ObjectSet objects;
  std::vector<GLint> objectFirst, objectCount;
  glm::mat4 view{1}, proj{1};
  glm::vec3 eye{0};

  GlProgram terrainProgram, skyProgram, objectProgram;
  GlVertexArray terrainVao, objectVao, skyVao;
  GlBuffer terrainVbo, objectVbo;
  std::vector<GlBuffer> levelIbo;
  GlTexture lightmapTex, albedoTex, skyTex, visibilityTex;
  GlFramebuffer fbo;
  GlRenderbuffer colorRb, depthRb;
};

Renderer::Renderer(const lighting::Terrain& terrain, const lighting::FloatImage& albedo, const RenderSettings& s,
                   const GlContextFactory& contextFactory)
    : gl_(std::make_unique<Gl>()) {
  Gl& g = *gl_;
  if (s.width < 16 || s.height < 16 || s.width > 8192 || s.height > 8192) {
    throw RenderError("picture size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                      " is outside 16..8192 pixels per side");
  }
  if (!albedo.empty() && (albedo.width != terrain.width || albedo.height != terrain.height || albedo.channels != 3)) {
    throw RenderError("the albedo map must be RGB of the terrain's size");
  }
  g.settings = s;
  g.width = s.width;
  g.height = s.height;
  g.terrain = &terrain;
  g.camera = s.camera ? *s.camera : automaticCamera(terrain);
  checkCamera(g.camera, terrain);
  if (!contextFactory) throw RenderError("no GL context available: no context factory");
  g.context = contextFactory();
  if (!g.context) throw RenderError("no GL context available: the context factory returned nothing");

  const float cell = static_cast<float>(terrain.cellSize);
  g.mesh = buildTerrainMesh(terrain, s.patchCells);
  const float extent = std::max(g.mesh.extentX, g.mesh.extentZ);
  if (g.settings.hazeDistance <= 0) g.settings.hazeDistance = 1.5f * extent;
  if (g.settings.lodDistance <= 0) g.settings.lodDistance = 1.5f * static_cast<float>(s.patchCells) * cell;
  if (g.settings.objectScale <= 0) g.settings.objectScale = cell / 4;
  if (g.settings.groundOffset <= 0) g.settings.groundOffset = cell;

  // Camera matrices.
  const CameraPlacement& c = g.camera;
  g.eye = glm::vec3(c.eyeX, terrainHeightAt(terrain, c.eyeX, c.eyeZ) + c.eyeHeight, c.eyeZ);
  const glm::vec3 target(c.targetX, terrainHeightAt(terrain, c.targetX, c.targetZ), c.targetZ);
  g.view = glm::lookAt(g.eye, target, glm::vec3(0, 1, 0));
  const float diag = std::sqrt(g.mesh.extentX * g.mesh.extentX + g.mesh.extentZ * g.mesh.extentZ) +
                     (g.mesh.maxHeight - g.mesh.minHeight) + c.eyeHeight;
  g.proj = glm::perspective(glm::radians(s.fovDeg), static_cast<float>(s.width) / static_cast<float>(s.height),
                            std::max(0.5f, c.eyeHeight * 0.05f), 2.0f * diag);

  // Framebuffer: RGBA8 colour + 24-bit depth.
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  g.fbo = GlFramebuffer(id);
  glGenRenderbuffers(1, &id);
  g.colorRb = GlRenderbuffer(id);
  glGenRenderbuffers(1, &id);
  g.depthRb = GlRenderbuffer(id);
  glBindRenderbuffer(GL_RENDERBUFFER, g.colorRb.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, s.width, s.height);
  glBindRenderbuffer(GL_RENDERBUFFER, g.depthRb.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, s.width, s.height);
  glBindFramebuffer(GL_FRAMEBUFFER, g.fbo.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.colorRb.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g.depthRb.id());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RenderError("the GL framebuffer for " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                      " is incomplete");
  }

  g.terrainProgram = GlProgram("terrain", shaders::kTerrainVertex, fragment(shaders::kTerrainFragment).c_str());
  g.skyProgram = GlProgram("sky", shaders::kSkyVertex, fragment(shaders::kSkyFragment).c_str());
  g.objectProgram = GlProgram("object", shaders::kObjectVertex, fragment(shaders::kObjectFragment).c_str());

  // Terrain geometry: one vertex buffer for every patch, one index buffer per level.
  g.terrainVao = makeVertexArray();
  glBindVertexArray(g.terrainVao.id());
  g.terrainVbo = makeBuffer();
  glBindBuffer(GL_ARRAY_BUFFER, g.terrainVbo.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(g.mesh.positions.size() * sizeof(float)),
               g.mesh.positions.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  for (const auto& idx : g.mesh.indices) {
    g.levelIbo.push_back(makeBuffer());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.levelIbo.back().id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(),
                 GL_STATIC_DRAW);
  }

  // Objects: in a group on the ground in front of the camera.
  if (s.objects) {
    // Twelve cells in front of the eye: near enough to see, spread over a few lightmap texels.
    const float dx = c.targetX - c.eyeX, dz = c.targetZ - c.eyeZ, len = std::sqrt(dx * dx + dz * dz);
    const float ahead = std::min(len * 0.5f, 12.0f * cell);
    const float siteX = c.eyeX + dx / len * ahead, siteZ = c.eyeZ + dz / len * ahead;
    g.objects = objectSet(terrain, siteX, siteZ, c.eyeX, c.eyeZ, g.settings.objectScale);
    std::vector<float> all;
    for (const Mesh& m : g.objects.meshes) {
      g.objectFirst.push_back(static_cast<GLint>(all.size() / 6));
      g.objectCount.push_back(static_cast<GLint>(m.vertices.size() / 6));
      all.insert(all.end(), m.vertices.begin(), m.vertices.end());
    }
    g.objectVao = makeVertexArray();
    glBindVertexArray(g.objectVao.id());
    g.objectVbo = makeBuffer();
    glBindBuffer(GL_ARRAY_BUFFER, g.objectVbo.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(all.size() * sizeof(float)), all.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    // OpenGL takes a buffer offset as a pointer.
    // NOLINTNEXTLINE(performance-no-int-to-ptr)
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
  }
  g.skyVao = makeVertexArray();  // core profile: a VAO even for attribute-less drawing
  glBindVertexArray(0);

  // Textures: albedo (static), lightmap, sky, sun visibility (per frame).
  g.albedoTex = makeTexture();
  glBindTexture(GL_TEXTURE_2D, g.albedoTex.id());
  textureParams(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  if (albedo.empty()) {
    const float grey[3] = {terrain.defaultAlbedo, terrain.defaultAlbedo, terrain.defaultAlbedo};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, 1, 1, 0, GL_RGB, GL_FLOAT, grey);
  } else {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, albedo.width, albedo.height, 0, GL_RGB, GL_FLOAT, albedo.pixels.data());
  }
  g.lightmapTex = makeTexture();
  glBindTexture(GL_TEXTURE_2D, g.lightmapTex.id());
  textureParams(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  g.skyTex = makeTexture();
  glBindTexture(GL_TEXTURE_2D, g.skyTex.id());
  textureParams(GL_REPEAT, GL_CLAMP_TO_EDGE);
  g.visibilityTex = makeTexture();
  glBindTexture(GL_TEXTURE_2D, g.visibilityTex.id());
  textureParams(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  checkGl("renderer set-up");
}

Renderer::~Renderer() = default;

std::string Renderer::contextDescription() const {
  return gl_->context->describe();
}

const CameraPlacement& Renderer::camera() const {
  return gl_->camera;
}

std::vector<std::array<float, 3>> Renderer::objectPositions() const {
  std::vector<std::array<float, 3>> out;
  for (const PlacedObject& o : gl_->objects.objects) out.push_back({o.position[0], o.position[1], o.position[2]});
  return out;
}

Rgba8Image Renderer::render(const Rgba8Image& lightmap, const Rgba8Image* sky, const FrameLight& light) {
  Gl& g = *gl_;
  const lighting::Terrain& t = *g.terrain;
  if (lightmap.width != t.width || lightmap.height != t.height) {
    throw RenderError("the lightmap is " + std::to_string(lightmap.width) + "x" + std::to_string(lightmap.height) +
                      " but the terrain is " + std::to_string(t.width) + "x" + std::to_string(t.height));
  }
  if (static_cast<std::size_t>(light.width) * light.height != light.sunVisibility.size() || light.width != t.width ||
      light.height != t.height) {
    throw RenderError("the frame's sun visibility does not match the terrain");
  }
  g.context->makeCurrent();
  uploadSrgb(g.lightmapTex.id(), lightmap);
  if (sky != nullptr && sky->width > 0) {
    uploadSrgb(g.skyTex.id(), *sky);
  } else {
    const std::uint8_t grey[4] = {128, 128, 128, 128};
    glBindTexture(GL_TEXTURE_2D, g.skyTex.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey);
  }
  glBindTexture(GL_TEXTURE_2D, g.visibilityTex.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, light.width, light.height, 0, GL_RED, GL_FLOAT, light.sunVisibility.data());

  glBindFramebuffer(GL_FRAMEBUFFER, g.fbo.id());
  glViewport(0, 0, g.width, g.height);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);

  const glm::mat4 viewProj = g.proj * g.view;
  const glm::mat4 invViewProj = glm::inverse(viewProj);
  const float cell = static_cast<float>(t.cellSize);
  const glm::vec2 texel(1.0f / (cell * static_cast<float>(t.width)), 1.0f / (cell * static_cast<float>(t.height)));
  const glm::vec2 halfTexel(0.5f / static_cast<float>(t.width), 0.5f / static_cast<float>(t.height));

  auto common = [&](const GlProgram& p) {
    glUseProgram(p.id());
    glUniform1i(p.uniform("uSky"), 0);
    glUniform3fv(p.uniform("uEye"), 1, glm::value_ptr(g.eye));
    glUniform1f(p.uniform("uHazeDistance"), g.settings.hazeDistance);
    glUniform1f(p.uniform("uExposure"), g.settings.exposure);
    glUniform1i(p.uniform("uLightmap"), 1);
    glUniform1i(p.uniform("uAlbedo"), 2);
    glUniform1i(p.uniform("uSunVisibility"), 3);
    glUniformMatrix4fv(p.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform2fv(p.uniform("uTexel"), 1, glm::value_ptr(texel));
    glUniform2fv(p.uniform("uHalfTexel"), 1, glm::value_ptr(halfTexel));
  };
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, g.skyTex.id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, g.lightmapTex.id());
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, g.albedoTex.id());
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_2D, g.visibilityTex.id());

  stats_ = RenderStats{};
  // Terrain, patch by patch at its level.
  common(g.terrainProgram);
  glBindVertexArray(g.terrainVao.id());
  const float eye[3] = {g.eye.x, g.eye.y, g.eye.z};
  const std::vector<int> levels = selectLevels(g.mesh, eye, g.settings.lodDistance, glm::value_ptr(viewProj));
  for (int level = 0; level < g.mesh.levels; ++level) {
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.levelIbo[static_cast<std::size_t>(level)].id());
    const auto count = static_cast<GLsizei>(g.mesh.indices[static_cast<std::size_t>(level)].size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
      if (levels[i] != level) continue;
      glDrawElementsBaseVertex(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr, g.mesh.patches[i].baseVertex);
      ++stats_.patchesDrawn;
      stats_.trianglesDrawn += count / 3;
    }
  }
  stats_.patchesCulled = static_cast<std::int64_t>(std::count(levels.begin(), levels.end(), -1));

  // Objects.
  if (!g.objects.objects.empty()) {
    common(g.objectProgram);
    const GlProgram& p = g.objectProgram;
    glUniform3fv(p.uniform("uSunDir"), 1, light.sunDirection.data());
    glUniform3fv(p.uniform("uSunIrradiance"), 1, light.sunIrradiance.data());
    glUniform3fv(p.uniform("uSkyIrradiance"), 1, light.skyIrradiance.data());
    glUniform1f(p.uniform("uGroundOffset"), g.settings.groundOffset);
    glBindVertexArray(g.objectVao.id());
    for (const PlacedObject& o : g.objects.objects) {
      glm::mat4 model = glm::translate(glm::mat4(1), glm::vec3(o.position[0], o.position[1], o.position[2]));
      model = glm::rotate(model, o.yawRad, glm::vec3(0, 1, 0));
      model = glm::scale(model, glm::vec3(o.scale));
      const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
      glUniformMatrix4fv(p.uniform("uModel"), 1, GL_FALSE, glm::value_ptr(model));
      glUniformMatrix3fv(p.uniform("uNormalMatrix"), 1, GL_FALSE, glm::value_ptr(normalMatrix));
      glUniform3fv(p.uniform("uObjectAlbedo"), 1, o.albedo);
      const auto m = static_cast<std::size_t>(o.mesh);
      glDrawArrays(GL_TRIANGLES, g.objectFirst[m], g.objectCount[m]);
      stats_.trianglesDrawn += g.objectCount[m] / 3;
    }
  }

  // Sky last, only where nothing was drawn (depth test LEQUAL at the far plane).
  common(g.skyProgram);
  glUniformMatrix4fv(g.skyProgram.uniform("uInvViewProj"), 1, GL_FALSE, glm::value_ptr(invViewProj));
  glBindVertexArray(g.skyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);

  // Read back; GL's rows are bottom-up, the image's top-down.
  Rgba8Image out(g.width, g.height);
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(g.width) * g.height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, g.width, g.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  checkGl("rendering a frame");
  const std::size_t stride = static_cast<std::size_t>(g.width) * 4;
  for (int y = 0; y < g.height; ++y) {
    std::copy_n(rows.data() + static_cast<std::size_t>(g.height - 1 - y) * stride, stride,
                out.pixels.data() + static_cast<std::size_t>(y) * stride);
  }
  return out;
}

}  // namespace vbim::render
