# Render the particles of a psmpm run at several times side by side, with
# ParaView, headless, into one PNG (one panel per time, one colour scale):
#   xvfb-run -a pvbatch contrib/render/render_bodies.py OUTPUT_DIR FIELD MIN MAX PNG T1 [T2 ...]
# FIELD is a point field of particles.pvd (body_id, material_id,
# stress_yy, ...; "velocity" is coloured by its magnitude). The grid is
# drawn as a wireframe; each panel is titled with its time.
# e.g. (doc/scenes.md):
#   build/psmpm prm/ring_impact.prm --set "Output directory=/tmp/ring" \
#     --set "Output/Interval=20"
#   xvfb-run -a pvbatch contrib/render/render_bodies.py /tmp/ring stress_yy -2e4 2e3 \
#     doc/images/ring_impact.png 0 0.15 0.25 0.4
import os
import sys
import tempfile

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, Glyph, PVDReader, Render, SaveScreenshot, Show,
                             Text)

directory, field = sys.argv[1], sys.argv[2]
low, high, png = float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
times = [float(t) for t in sys.argv[6:]]
view = GetActiveViewOrCreate("RenderView")
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.OrientationAxesVisibility = 0

grid = PVDReader(FileName=os.path.join(directory, "grid.pvd"))
# Panel and dots sized by the domain, so that a 3 x 1.25 m column and a
# unit square both fill their panels.
grid.UpdatePipeline(times[0] if times else 0)
x0, x1, y0, y1 = grid.GetDataInformation().GetBounds()[:4]
width = x1 - x0
size = [600, int(600 * (y1 - y0) / width) + 160]
view.ViewSize = size
g = Show(grid, view)
g.SetRepresentationType("Wireframe")
g.AmbientColor = g.DiffuseColor = [0.75, 0.75, 0.75]

particles = PVDReader(FileName=os.path.join(directory, "particles.pvd"))
dots = Glyph(Input=particles, GlyphType="Sphere")
dots.ScaleArray = ["POINTS", "No scale array"]
dots.ScaleFactor = 0.012 * width
dots.GlyphMode = "All Points"
d = Show(dots, view)
ColorBy(d, ("POINTS", field, "Magnitude") if field == "velocity" else ("POINTS", field))
lut = GetColorTransferFunction(field)
lut.ApplyPreset("Viridis (matplotlib)", True)
lut.RescaleTransferFunction(low, high)
d.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = field
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
title = Text()
t = Show(title, view)
t.Color = [0, 0, 0]
t.WindowLocation = "Upper Center"

panels = []
scratch = tempfile.mkdtemp()
for k, time in enumerate(times):
    view.ViewTime = time
    title.Text = "t = %g s" % time
    view.ResetCamera()
    Render(view)
    name = os.path.join(scratch, "panel%02d.png" % k)
    SaveScreenshot(name, view, ImageResolution=size)
    panels.append(name)

# One image: the panels in a row (vtk's own PNG reader and append filter,
# so that pvbatch needs no further Python packages).
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
row = vtkImageAppend()
row.SetAppendAxis(0)
for name in panels:
    r = vtkPNGReader()
    r.SetFileName(name)
    r.Update()
    row.AddInputData(r.GetOutput())
row.Update()
w = vtkPNGWriter()
w.SetFileName(png)
w.SetInputData(row.GetOutput())
w.Write()
for name in panels:
    os.remove(name)
os.rmdir(scratch)
print("wrote", png)
