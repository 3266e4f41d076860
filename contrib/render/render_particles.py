# Render MPM particles (and the grid) from a psmpm output directory with
# ParaView, headless:
#   xvfb-run -a pvbatch contrib/render/render_particles.py OUTPUT_DIR FIELD TIME PNG
# e.g. the large soil column on 1 x 8 blocks at its deepest compression:
#   build/psmpm prm/soil_column_large.prm --set "Mesh/Blocks y=8" \
#     --set "Output/Interval=100" --set "Output directory=/tmp/col"
#   xvfb-run -a pvbatch contrib/render/render_particles.py /tmp/col stress_yy 0.2 \
#     doc/images/soil_column_large_particles.png
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, Glyph, PVDReader, Render, SaveScreenshot, Show)

directory, field, time, png = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [700, 1000]
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.OrientationAxesVisibility = 0
view.ViewTime = time

grid = PVDReader(FileName=directory + "/grid.pvd")
g = Show(grid, view)
g.SetRepresentationType("Wireframe")
g.AmbientColor = g.DiffuseColor = [0.4, 0.4, 0.4]

particles = PVDReader(FileName=directory + "/particles.pvd")
dots = Glyph(Input=particles, GlyphType="Sphere")
dots.ScaleArray = ["POINTS", "No scale array"]
dots.ScaleFactor = 0.006
dots.GlyphMode = "All Points"
d = Show(dots, view)
ColorBy(d, ("POINTS", field))
lut = GetColorTransferFunction(field)
lut.ApplyPreset("Viridis (matplotlib)", True)
d.RescaleTransferFunctionToDataRange(True, False)
d.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = field
bar.TitleColor = bar.LabelColor = [0, 0, 0]

view.ResetCamera()
Render(view)
SaveScreenshot(png, view, ImageResolution=[700, 1000])
