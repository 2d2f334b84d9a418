# FreeCAD CAM (Path workbench) side of the pocket benchmark of issue 35:
# builds bench/fine-pocket.taiwa's pocket in FreeCAD 0.20 headless, computes a
# Pocket Shape operation on it and posts it with the linuxcnc post-processor,
# timing the path and the post separately. Prints one machine-readable line:
#   freecad path_s=.. post_s=.. moves=.. arcs=.. lines=.. pattern=.. out=..
# Run (bench-only dependency: apt-get install freecad, Debian 12 = 0.20.2):
#   freecadcmd bench/freecad_pocket.py
# or through bench/compare-freecad.sh, which runs Taiwa's export beside it.
# Environment: FREECAD_POCKET_OUT=FILE keeps the posted tape there (default: a
# temporary file, deleted at the end); FREECAD_POCKET_PATTERN=Offset|ZigZag
# (default Offset, contour-parallel rings like Taiwa's roughing).
#
# The job is the one Taiwa's export machines for bench/fine-pocket.taiwa
# (see its fine-pocket.steps.json): stock block 140 x 100 x 30 at (0, 0), top
# at Z 0; pocket corners (20, 20)..(120, 80), corner radius 5.3, depth 20;
# unit U 9 (roughing only), so Taiwa roughs to the wall allowance 0.3 and the
# floor allowance 0.2: tool-edge outline (20.3, 20.3)..(119.7, 79.7), r 5.0,
# down to Z -19.8. Tool: library tool 27, flat end mill 10 mm carbide.
# Technology: gamma 0.02 (layer 0.2 mm = 0.02 x D), stepOver 0.02 (0.2 mm).
# Cutting data as on Taiwa's tape for aluminium-6061: S9549, F2292, plunge
# F917 (mm/min). Here: ExtraOffset +0.3 (leaves 0.3 on the walls: the tool
# centre runs X 25.3..114.7, Y 25.3..74.7 as Taiwa's), StartDepth 0,
# FinalDepth -19.8, StepDown 0.2 (99 levels), StepOver 2 %, climb, StartAt
# Center, KeepToolDown (rings linked at depth, no retract between them, as
# Taiwa links its rings). FreeCAD plunges straight down at each level (no
# ramp dressup); Taiwa helixes in. The timed path is the document recompute
# that computes the operation; the timed post is linuxcnc_post.export of
# what PathPost would hand it (the G54 fixture, the tool controller, the
# operation).

import os
import sys
import tempfile
import time

import FreeCAD
import Part
import Path

import PathScripts.PathJob as PathJob
import PathScripts.PathPocketShape as PathPocketShape
import PathScripts.PathToolBit as PathToolBit
import PathScripts.PathToolController as PathToolController
from PathScripts.PathPostProcessor import PostProcessor

V = FreeCAD.Vector

# The pocket of bench/fine-pocket.taiwa.
STOCK_W, STOCK_L, STOCK_H = 140.0, 100.0, 30.0
X0, Y0, X1, Y1 = 20.0, 20.0, 120.0, 80.0
CORNER_R = 5.3
DEPTH = 20.0
WALL_ALLOWANCE = 0.3   # alpha2, left by Taiwa's U 9 roughing
FLOOR_ALLOWANCE = 0.2  # beta2
TOOL_D = 10.0
STEP_OVER_PERCENT = 2  # stepOver 0.02 x D
STEP_DOWN = 0.2        # gamma 0.02 x D
SPINDLE = 9549.0
FEED = 2292.0          # mm/min
PLUNGE = 917.0         # mm/min
PATTERN = os.environ.get("FREECAD_POCKET_PATTERN", "Offset")


def log(msg):
    sys.stderr.write("freecad_pocket: " + msg + "\n")


def rounded_rect_face(x0, y0, x1, y1, r, z):
    core = Part.Face(Part.makePolygon([
        V(x0 + r, y0 + r, z), V(x1 - r, y0 + r, z), V(x1 - r, y1 - r, z),
        V(x0 + r, y1 - r, z), V(x0 + r, y0 + r, z)]))
    return core.makeOffset2D(r, 0)  # join 0: arcs at the corners


def build_model(doc):
    stock = Part.makeBox(STOCK_W, STOCK_L, STOCK_H, V(0, 0, -STOCK_H))
    cavity = rounded_rect_face(X0, Y0, X1, Y1, CORNER_R, -DEPTH).extrude(
        V(0, 0, DEPTH + 1.0))
    solid = stock.cut(cavity)
    solid = solid.removeSplitter()
    part = doc.addObject("Part::Feature", "FinePocket")
    part.Shape = solid
    return part


def floor_face_name(shape):
    for i, f in enumerate(shape.Faces):
        bb = f.BoundBox
        if abs(bb.ZMin + DEPTH) < 1e-6 and abs(bb.ZMax + DEPTH) < 1e-6:
            return "Face%d" % (i + 1)
    raise RuntimeError("no pocket floor face found")


class _Fixture:
    """What PathPost.buildPostList gives the post for the work offset."""

    def __init__(self, name, z):
        self.Label = name
        self.Name = name
        self.Path = Path.Path([Path.Command(name), Path.Command("G0 Z%g" % z)])


def main():
    doc = FreeCAD.newDocument("FinePocket")
    model = build_model(doc)
    doc.recompute()

    job = PathJob.Create("Job", [model])
    doc.recompute()
    job.PostProcessor = "linuxcnc"
    job.PostProcessorArgs = "--no-show-editor"

    # One 10 mm flat end mill (FreeCAD's endmill shape), replacing the job's
    # default tool controller.
    bit = PathToolBit.Factory.Create("Endmill10", "endmill.fcstd")
    bit.Diameter = TOOL_D
    bit.CuttingEdgeHeight = 30.0
    bit.Length = 60.0
    tc = PathToolController.Create("TC: Endmill 10", tool=bit, toolNumber=27)
    tc.SpindleSpeed = SPINDLE
    tc.SpindleDir = "Forward"
    tc.HorizFeed = "%g mm/min" % FEED
    tc.VertFeed = "%g mm/min" % PLUNGE
    for old in list(job.Tools.Group):
        job.Tools.removeObject(old)
        doc.removeObject(old.Name)
    job.Proxy.addToolController(tc)
    doc.recompute()

    clone = job.Model.Group[0]
    face = floor_face_name(clone.Shape)

    op = PathPocketShape.Create("Pocket")
    job.Proxy.addOperation(op)
    op.ToolController = tc
    op.Base = [(clone, [face])]
    for prop in ("StartDepth", "FinalDepth", "StepDown", "SafeHeight",
                 "ClearanceHeight"):
        op.setExpression(prop, None)
    op.StartDepth = 0.0
    op.FinalDepth = -(DEPTH - FLOOR_ALLOWANCE)
    op.FinishDepth = 0.0
    op.StepDown = STEP_DOWN
    op.SafeHeight = 5.0
    op.ClearanceHeight = 10.0
    op.StepOver = STEP_OVER_PERCENT
    op.OffsetPattern = PATTERN
    op.CutMode = "Climb"
    op.StartAt = "Center"
    op.ExtraOffset = WALL_ALLOWANCE  # positive leaves stock on the walls
    op.KeepToolDown = True  # no retract between rings (Taiwa links them)
    op.UseStartPoint = False

    t0 = time.perf_counter()
    doc.recompute()
    path_s = time.perf_counter() - t0
    if "Invalid" in op.State or not op.Path.Commands:
        log("the operation failed: state %s" % (op.State,))
        return 1

    cmds = op.Path.Commands
    moves = sum(1 for c in cmds if c.Name in ("G0", "G00", "G1", "G01", "G2",
                                              "G02", "G3", "G03"))
    arcs = sum(1 for c in cmds if c.Name in ("G2", "G02", "G3", "G03"))
    zs = sorted({round(c.Parameters["Z"], 4) for c in cmds
                 if c.Name in ("G1", "G01", "G2", "G02", "G3", "G03")
                 and "Z" in c.Parameters})
    xs = [c.Parameters["X"] for c in cmds if "X" in c.Parameters]
    ys = [c.Parameters["Y"] for c in cmds if "Y" in c.Parameters]
    zmin = min(c.Parameters["Z"] for c in cmds if "Z" in c.Parameters)

    keep = os.environ.get("FREECAD_POCKET_OUT")
    if keep:
        out = keep
    else:
        fd, out = tempfile.mkstemp(prefix="freecad-pocket-", suffix=".ngc")
        os.close(fd)
    fixture = _Fixture(job.Fixtures[0] if job.Fixtures else "G54",
                       job.Stock.Shape.BoundBox.ZMax
                       + job.SetupSheet.ClearanceHeightOffset.Value)
    post = PostProcessor.load("linuxcnc")
    t0 = time.perf_counter()
    post.export([fixture, tc, op], out, job.PostProcessorArgs)
    post_s = time.perf_counter() - t0
    with open(out) as f:
        lines = sum(1 for _ in f)
    if not keep:
        os.unlink(out)

    log("pattern %s, tool path X %.3f..%.3f Y %.3f..%.3f, lowest Z %.3f, "
        "%d cutting levels" % (PATTERN, min(xs), max(xs), min(ys), max(ys),
                               zmin, len(zs)))
    print("freecad path_s=%.3f post_s=%.3f moves=%d arcs=%d lines=%d "
          "pattern=%s out=%s" % (path_s, post_s, moves, arcs, lines, PATTERN,
                                 out if keep else "-"))
    sys.stdout.flush()
    return 0


rc = main()
if rc:
    sys.exit(rc)
