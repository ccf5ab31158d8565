"""Scene: TOML files → frozen, validated settings, and time — frame times, camera and sun motion
(:mod:`.motion`), the arrays a scene names (:mod:`.arrays`). The bottom stage: it knows no physics
beyond its inputs and imports only ``oceanrender.io``."""

from .settings import (
    CameraSettings,
    EnvironmentSettings,
    FoamSettings,
    OBJECT_MATERIALS,
    MeshSettings,
    ObjectSettings,
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
    with_view,
)

__all__ = [
    "CameraSettings", "EnvironmentSettings", "FoamSettings", "MeshSettings", "OBJECT_MATERIALS", "ObjectSettings", "OceanSettings", "OutputSettings", "RenderSettings", "Scene", "SceneError",
    "SunSettings", "VisionSettings", "WaterSettings", "load_scene", "scene_from_dict", "with_overrides", "with_view",
]
