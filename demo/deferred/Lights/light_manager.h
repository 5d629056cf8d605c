/// <summary>
/// A Manager for all the light types
/// </summary>
// Lights.LightManager (seed 000, chapters 3-5, in its chapter 5 form). C#'s lists of references
// become vectors of owning pointers: AddLight(new ...) hands the light over, RemoveLight(light)
// destroys it.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "deferred/Lights/directional_light.h"
#include "deferred/Lights/point_light.h"
#include "deferred/Lights/shadow_map_key.h"
#include "deferred/Lights/spot_light.h"
#include "deferred/xna.h"

namespace TheCansinDeferredRenderer::Lights {

class LightManager {
    //Directional Lights
    std::vector<std::unique_ptr<DirectionalLight>> directionalLights;
    //Spot Lights
    std::vector<std::unique_ptr<SpotLight>> spotLights;
    //Point Lights
    std::vector<std::unique_ptr<PointLight>> pointLights;
    //Depth Writing Shader
    // fxport: loaded with the first shadow map drawn (nullptr before): a scene without shadowed
    // lights never compiles it.
    Effect* depthWriter = nullptr;
    ContentManager& content;
    // fxport (issue 16): the key each light's shadow map was last drawn with.
    std::map<const void*, ShadowMapKey> shadowMapKeys;

public:
    // #region Get Functions
    //Get Directional Lights
    const std::vector<std::unique_ptr<DirectionalLight>>& getDirectionalLights() const { return directionalLights; }
    //Get Spot Lights
    const std::vector<std::unique_ptr<SpotLight>>& getSpotLights() const { return spotLights; }
    //Get Point Lights
    const std::vector<std::unique_ptr<PointLight>>& getPointLights() const { return pointLights; }
    // #endregion

    //Constructor
    explicit LightManager(ContentManager& Content);

    //Add a Directional Light
    void AddLight(std::unique_ptr<DirectionalLight> Light);
    //Add a Spot Light
    void AddLight(std::unique_ptr<SpotLight> Light);
    //Add a Point Light
    void AddLight(std::unique_ptr<PointLight> Light);
    //Remove a Directional Light
    void RemoveLight(DirectionalLight* Light);
    //Remove a Spot Light
    void RemoveLight(SpotLight* Light);
    //Remove a Point Light
    void RemoveLight(PointLight* Light);

    //Draw Shadow Maps
    // fxport: spotVisible/pointVisible (when given) say whether the camera sees a light's volume; a
    // light it does not see lights no pixel, so its shadow map is not drawn (nor made) this frame.
    void DrawShadowMaps(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models,
                        const std::function<bool(const SpotLight&)>& spotVisible = {},
                        const std::function<bool(const PointLight&)>& pointVisible = {});

    // fxport: whether any light casts shadows (else Game1 runs no shadow-map pass at all).
    bool HasShadowedLights() const;

    // fxport (issue 16): a shadow map whose key (ShadowMapKey: the light's matrices and values, the
    // map, the casters' transforms and draws) is the one it was last drawn with is kept as it is
    // instead of redrawn (the seed redraws every map every frame); the same image. False redraws
    // every frame (fxdemo deferred --no-shadow-cache). The counts add up over the frames.
    bool reuseShadowMaps = true;
    int shadowMapsDrawn = 0;
    int shadowMapsReused = 0;

private:
    //Draw a Shadow Map for a Spot Light
    void DrawShadowMap(GraphicsDevice& GraphicsDevice, SpotLight& Light, const std::vector<Model*>& Models);
    //Draw a Shadow Map for a Point Light
    void DrawShadowMap(GraphicsDevice& GraphicsDevice, PointLight& Light, const std::vector<Model*>& Models);
    //Draw Models
    void DrawModels(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models);
    // fxport: whether `Light`'s map must be drawn (its key changed, or the cache is off); counts.
    bool ShadowMapOutdated(const void* Light, const ShadowMapKey& key);
};

}  // namespace TheCansinDeferredRenderer::Lights
