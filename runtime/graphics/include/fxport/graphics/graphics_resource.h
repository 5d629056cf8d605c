// Base of every object that owns GPU memory (textures, targets, buffers, effects). Resources are
// neither copied nor moved: the device refers to them by address while they are bound. Own them the
// way your port likes (members, std::unique_ptr, std::shared_ptr); destroying one, or calling
// Dispose(), frees its GL objects at once and unbinds it from the device, so nothing dangles. A
// device destroyed first disposes what is left; using such a resource afterwards throws.
#pragma once

#include <string>

namespace fxport {

class GraphicsDevice;

class GraphicsResource {
public:
    GraphicsResource(const GraphicsResource&) = delete;
    GraphicsResource& operator=(const GraphicsResource&) = delete;
    virtual ~GraphicsResource();

    // Frees the GL objects now (XNA's Dispose). Using the resource afterwards throws InvalidOperation.
    void Dispose();
    bool IsDisposed() const { return disposed_; }
    fxport::GraphicsDevice& device() const { return *device_; }

    std::string Name;  // for messages and debug labels; XNA's GraphicsResource.Name

protected:
    explicit GraphicsResource(fxport::GraphicsDevice& device, const char* kind);
    // Releases GL objects; called once, by Dispose() or the destructor of the most derived class.
    virtual void releaseGpuObjects() = 0;
    // Every derived destructor calls this so releaseGpuObjects runs while the object is whole.
    void disposeFromDestructor();
    // Throws InvalidOperation naming the resource when it was disposed.
    void throwIfDisposed(const char* operation) const;
    // "RenderTarget2D 'GBuffer0'" / "RenderTarget2D #3" for messages.
    std::string describe() const;

private:
    friend class GraphicsDevice;  // cuts resources loose when it is destroyed before them
    fxport::GraphicsDevice* device_;
    const char* kind_;
    int serial_;
    bool disposed_ = false;
};

}  // namespace fxport
