"""Scene configuration: TOML files → frozen, validated settings."""

from .scene import (
    CameraSettings,
    OceanSettings,
    OutputSettings,
    RenderSettings,
    Scene,
    SceneError,
    SunSettings,
    VisionSettings,
    WaterSettings,
    load_scene,
    scene_from_dict,
    with_overrides,
)

__all__ = [
    "CameraSettings", "OceanSettings", "OutputSettings", "RenderSettings", "Scene", "SceneError",
    "SunSettings", "VisionSettings", "WaterSettings", "load_scene", "scene_from_dict", "with_overrides",
]
