// One frame of the scene: the terrain mesh (with LOD) coloured diffuse x lightmap, the streamed sky
// dome behind it, distance haze, and the hemisphere-lit objects, drawn by GL 4.5 core (OSMesa,
// llvmpipe) into a framebuffer object and read back top-down.
//
// Per-frame use (e.g. live, from `vbim play --render`, inside the player's frame sink):
//
//   render::SceneLighting lighting(terrain, dayParams);          // once: precompute
//   render::Renderer renderer(terrain, albedo, settings);        // once: GL context, mesh, textures
//   ... for each shown frame (lightmap, sky as the player holds them):
//   render::FrameLight light = lighting.evaluate(row.lightmap.targetSeq, lightmap, &sky);
//   Rgba8Image picture = renderer.render(lightmap, &sky, light);
//
// The picture is deterministic: llvmpipe gives the same bytes for any LP_NUM_THREADS (tested).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "lighting/float_image.hpp"
#include "lighting/terrain.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/scene_lighting.hpp"
#include "runtime/image.hpp"

namespace vbim::render {

struct RenderStats {
  std::int64_t patchesDrawn = 0;
  std::int64_t patchesCulled = 0;
  std::int64_t trianglesDrawn = 0;  // terrain + objects, last frame
};

class Renderer {
 public:
  // Makes the context (RenderError "no GL context available: ..." if the factory fails), builds the
  // mesh, compiles the shaders. `albedo`: RGB linear of the terrain's size, or empty for a uniform grey.
  // Throws RenderError for a camera outside the terrain.
  Renderer(const lighting::Terrain& terrain, const lighting::FloatImage& albedo, const RenderSettings& settings,
           const GlContextFactory& contextFactory = defaultContextFactory());
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // `lightmap` must have the terrain's size; `sky` may be null (a flat grey sky).
  Rgba8Image render(const Rgba8Image& lightmap, const Rgba8Image* sky, const FrameLight& light);

  const RenderStats& stats() const { return stats_; }
  std::string contextDescription() const;
  const CameraPlacement& camera() const;
  // Where the objects stand (world metres); empty with settings.objects = false.
  std::vector<std::array<float, 3>> objectPositions() const;

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
  RenderStats stats_;
};

}  // namespace vbim::render
