"""Scene configuration: TOML files → frozen, validated settings."""

from .scene import (
    CameraSettings,
    FoamSettings,
    MeshSettings,
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
    "CameraSettings", "FoamSettings", "MeshSettings", "OceanSettings", "OutputSettings", "RenderSettings", "Scene", "SceneError",
    "SunSettings", "VisionSettings", "WaterSettings", "load_scene", "scene_from_dict", "with_overrides",
]
