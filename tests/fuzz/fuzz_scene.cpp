// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes the YAML scene reader, then plans and renders what it accepts at
// 4×3 pixels, planned and literal: every accepted scene renders finite.
#include "FuzzCheck.h"
#include "render/SceneFile.h"
#include "render/SceneRenderer.h"

using namespace bandlight;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string source = "/nonexistent/fuzz.yaml";
    Scene scene;
    try
    {
        scene = ReadSceneText(fuzz::Text(data, size), source);
    }
    catch (const Exception& e)
    {
        fuzz::CheckMessage(e, source);
        return 0;
    }
    scene.camera.width = 4;
    scene.camera.height = 3;
    ScenePlan plan;
    try
    {
        plan = PlanScene(scene);
    }
    catch (const Exception&)
    {
        return 0;
    }
    // Both paths render finite pixels, or refuse with the renderer's message.
    for (const bool planned : {true, false})
    {
        RenderedImage img;
        try
        {
            img = planned ? RenderScene(scene, plan, 1) : RenderSceneUnplanned(scene, 1);
        }
        catch (const Exception& e)
        {
            fuzz::CheckMessage(e, "the render overflowed");
            continue;
        }
        fuzz::Check(img.pixels.size() == size_t(4 * 3 * img.channels), "wrong image size");
        for (float v : img.pixels)
        {
            fuzz::Check(std::isfinite(v), "a rendered pixel is not finite");
        }
    }
    return 0;
}
