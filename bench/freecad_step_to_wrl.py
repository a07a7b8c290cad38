# FreeCAD side of bench/library_sizes.py: one STEP file -> one mesh VRML97 file, headless.
#
# Run by FreeCAD's command-line interpreter (no GUI), one process per part:
#
#   CADNURBS_FC_IN=part.step CADNURBS_FC_OUT=part.wrl CADNURBS_FC_DEVIATION=0.01 \
#   CADNURBS_FC_REPORT=part.json freecadcmd bench/freecad_step_to_wrl.py
#
# freecadcmd opens its further command-line arguments as documents, so the script takes its
# arguments from the environment. It reads the STEP with Part (OCCT's STEP reader, one compound, no
# colours), meshes it with MeshPart.meshFromShape (LinearDeflection = the deviation in mm, absolute;
# AngularDeflection CADNURBS_FC_ANGULAR, default 1.5 rad so that, as in bench_tessellation, only the
# deviation drives the mesh) and writes the mesh with the Mesh module, which picks VRML97 from the
# .wrl extension (one IndexedFaceSet, coordinates with 3 decimals). It writes a JSON report: the
# seconds spent importing FreeCAD's modules, reading, meshing and writing, and counts. freecadcmd's
# exit status does not say whether the script failed: the report's "ok" does.
import json
import os
import time
import traceback

t_start = time.perf_counter()
report = {"ok": False}
try:
    import FreeCAD
    import Part
    import Mesh  # noqa: F401  (registers the mesh file formats)
    import MeshPart

    report["freecad_version"] = ".".join(FreeCAD.Version()[:3]).strip(".")
    t_modules = time.perf_counter()
    path_in = os.environ["CADNURBS_FC_IN"]
    path_out = os.environ["CADNURBS_FC_OUT"]
    deviation = float(os.environ.get("CADNURBS_FC_DEVIATION", "0.01"))
    angular = float(os.environ.get("CADNURBS_FC_ANGULAR", "1.5"))

    shape = Part.Shape()
    shape.read(path_in)
    t_read = time.perf_counter()
    mesh = MeshPart.meshFromShape(Shape=shape, LinearDeflection=deviation, AngularDeflection=angular,
                                  Relative=False)
    t_mesh = time.perf_counter()
    mesh.write(path_out)
    t_write = time.perf_counter()

    report.update({
        "ok": True,
        "faces": len(shape.Faces),
        "triangles": mesh.CountFacets,
        "points": mesh.CountPoints,
        "deviation": deviation,
        "angular_deflection": angular,
        "seconds_modules": t_modules - t_start,
        "seconds_read": t_read - t_modules,
        "seconds_mesh": t_mesh - t_read,
        "seconds_write": t_write - t_mesh,
        "seconds_after_modules": t_write - t_modules,
    })
except Exception as e:  # reported, not raised: freecadcmd would hide the exit status anyway
    report["error"] = (type(e).__name__ + ": " + str(e)).splitlines()[0] if str(e) else type(e).__name__
    report["traceback"] = traceback.format_exc()

with open(os.environ.get("CADNURBS_FC_REPORT", "freecad_report.json"), "w") as f:
    json.dump(report, f)
