#include "deferred/Lights/spot_light.h"

#include <cmath>

namespace TheCansinDeferredRenderer::Lights {

//Constructor
SpotLight::SpotLight(GraphicsDevice& GraphicsDevice, Vector3 Position, Vector3 Direction, Vector4 Color,
                     float Intensity, bool isWithShadows, int ShadowMapResoloution, Texture2D* AttenuationTexture) {
    //Position
    setPosition(Position);
    //Direction
    setDirection(Direction);
    //Color
    setColor(Color);
    //Intensity
    setIntensity(Intensity);
    //NearPlane
    nearPlane = 1.0f;
    //FarPlane
    farPlane = 100.0f;
    //FOV
    FOV = MathHelper::PiOver2;
    //Set whether Is With Shadows
    setIsWithShadows(isWithShadows);
    //Shadow Map Resoloution
    shadowMapResoloution = ShadowMapResoloution;
    //Depth Bias
    depthBias = 1.0f / 2000.0f;
    //Projection
    // Reconstructed: seed 000 is cut here (the line break after "nearPlane," lost the last
    // argument; farPlane is the only one left, and DepthPrecision/LightHeight use it as the range).
    projection = Matrix::CreatePerspectiveFieldOfView(FOV, 1.0f, nearPlane, farPlane);
    //Shadow Map
    // fxport: made on first use (MakeShadowMap).
    graphicsDevice = &GraphicsDevice;
    //Attenuation Texture
    attenuationTexture = AttenuationTexture;
    //Create View and World
    Update();
}

RenderTarget2D& SpotLight::MakeShadowMap() {
    // The seed's map; made again if the resolution changed since.
    if (!shadowMap || shadowMap->Width() != getShadowMapResoloution()) {
        shadowMap = std::make_unique<RenderTarget2D>(*graphicsDevice, getShadowMapResoloution(),
                                                     getShadowMapResoloution(), false, SurfaceFormat::Single,
                                                     DepthFormat::Depth24Stencil8);
        shadowMap->Name = "SpotLight.shadowMap";
    }
    return *shadowMap;
}

//Calculate the Cosine of the LightAngle
float SpotLight::LightAngleCos() const {
    //float ConeAngle = 2 * atanf(Radius / Height);
    float ConeAngle = FOV;
    return float(std::cos(double(ConeAngle)));
}

//Update
void SpotLight::Update() {
    //Target
    Vector3 target = (position + direction);
    if (target == Vector3::Zero) target = -Vector3::Up;
    //Up
    Vector3 up = Vector3::Cross(direction, Vector3::Up);
    if (up == Vector3::Zero) up = Vector3::Right;
    else up = Vector3::Up;
    //ReMake View
    view = Matrix::CreateLookAt(position, target, up);
    //Make Scaling Factor
    float radial = float(std::tan(double(FOV) / 2.0)) * 2 * farPlane;
    //Make Scaling Matrix
    Matrix Scaling = Matrix::CreateScale(radial, radial, farPlane);
    //Make Translation Matrix
    Matrix Translation = Matrix::CreateTranslation(position.X, position.Y, position.Z);
    //Make Inverse View
    Matrix inverseView = Matrix::Invert(view);
    //Make Semi-Product
    Matrix semiProduct = Scaling * inverseView;
    //Decompose Semi-Product
    Vector3 S; Vector3 P; Quaternion Q;
    semiProduct.Decompose(S, Q, P);
    //Make Rotation
    Matrix Rotation = Matrix::CreateFromQuaternion(Q);
    //Make World
    world = Scaling * Rotation * Translation;
}

}  // namespace TheCansinDeferredRenderer::Lights
