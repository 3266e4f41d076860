# Render one Powell-Sabin basis function and a projection error from the
# VTU files of the L2 projection scene, headless:
#
#   xvfb-run -a pvbatch contrib/render/render_ps.py <scene output dir> <image dir>
#
# Writes ps_basis_function.png (the function warped by its value over the
# macro mesh and its Powell-Sabin refinement) and ps_projection_error.png
# (the error of the projection in colour, with the macro mesh).
import os
import sys

from paraview.simple import *

source, target = sys.argv[1], sys.argv[2]
os.makedirs(target, exist_ok=True)


def load(name):
    return XMLUnstructuredGridReader(FileName=[os.path.join(source, name)])


def wireframe(view, reader, color, width, z=0.0):
    shown = Show(reader, view)
    shown.SetRepresentationType('Wireframe')
    shown.ColorArrayName = [None, '']
    shown.AmbientColor = color
    shown.DiffuseColor = color
    shown.LineWidth = width
    shown.Position = [0.0, 0.0, z]
    return shown


projection = load('projection.vtu')
mesh = load('mesh.vtu')
refinement = load('ps_refinement.vtu')

# 1. The basis function, warped.
view = CreateView('RenderView')
view.ViewSize = [1200, 900]
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
# The patches are separate triangles: merge their points so that the
# surface gets smooth normals (the function is C1, the picture should be).
merged = CleantoGrid(Input=projection)
warp = WarpByScalar(Input=merged)
warp.Scalars = ['POINTS', 'basis_function']
warp.ScaleFactor = 1.0
smooth = GenerateSurfaceNormals(Input=ExtractSurface(Input=warp))
smooth.FeatureAngle = 60
shown = Show(smooth, view)
ColorBy(shown, ('POINTS', 'basis_function'))
lut = GetColorTransferFunction('basis_function')
lut.ApplyPreset('Viridis (matplotlib)', True)
shown.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = 'basis function'
bar.ComponentTitle = ''
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
wireframe(view, refinement, [0.6, 0.6, 0.6], 1.0)
wireframe(view, mesh, [0.0, 0.0, 0.0], 2.0)
view.CameraPosition = [2.2, -1.6, 1.9]
view.CameraFocalPoint = [0.5, 0.5, 0.15]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 30
Render(view)
SaveScreenshot(os.path.join(target, 'ps_basis_function.png'), view,
               ImageResolution=[1200, 900])
Delete(view)

# 2. The projection error, flat, with the mesh.
view = CreateView('RenderView')
view.ViewSize = [1000, 900]
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
shown = Show(projection, view)
ColorBy(shown, ('POINTS', 'error'))
lut = GetColorTransferFunction('error')
lut.ApplyPreset('Cool to Warm', True)
rng = projection.PointData['error'].GetRange()
m = max(abs(rng[0]), abs(rng[1]))
lut.RescaleTransferFunction(-m, m)
shown.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = 'projection error'
bar.ComponentTitle = ''
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
bar.RangeLabelFormat = '%-#6.1e'
wireframe(view, mesh, [0.0, 0.0, 0.0], 2.0, z=0.001)
view.CameraPosition = [0.5, 0.5, 3.0]
view.CameraFocalPoint = [0.5, 0.5, 0.0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.6
Render(view)
SaveScreenshot(os.path.join(target, 'ps_projection_error.png'), view,
               ImageResolution=[1000, 900])
