"""Export: files for other tools — Blender-layout wave maps, the camera mesh for
real-time engines, the optics report (CSV, JSON, plots). Built on ``oceanrender.io``'s
atomic writers; called by the CLI.
"""
