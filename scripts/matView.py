# fiberTracking: a picture of the mat on a wire from the fibers' VTK series
# (wallInteraction rule mat).  Run with pvbatch (under xvfb-run where there
# is no display):
#   pvbatch scripts/matView.py <series> <png> [--time t] [--color
#           landTime|height] [--normal x|y|z]
# Draws the fibers in a mat (cell data matPatch >= 0) at time t (default:
# the last of the series) as tubes of their diameters, seen from above the
# wire (its normal along --normal, default y, into the domain) at an
# oblique angle, coloured by the time they joined the mat (landTime,
# default) or by the height of their segments above the lowest one, with a
# colour legend.  Prints 'matView: <t> <segments in the mat> <png>'.
import sys
from paraview.simple import (OpenDataFile, Show, Render, GetActiveViewOrCreate,
                             ColorBy, SaveScreenshot, ResetCamera, Threshold,
                             CellDatatoPointData, Tube, Calculator,
                             GetColorTransferFunction, GetScalarBar,
                             UpdatePipeline, ExtractSurface)
from paraview import servermanager as sm


def usage(msg):
    sys.stderr.write('matView.py: %s\nusage: pvbatch matView.py <series> '
                     '<png> [--time t] [--color landTime|height] '
                     '[--normal x|y|z]\n' % msg)
    sys.exit(1)


args, t, color, normal = [], None, 'landTime', 'y'
argv = sys.argv[1:]
while argv:
    a = argv.pop(0)
    if a in ('--time', '--color', '--normal'):
        if not argv:
            usage('%s needs a value' % a)
        v = argv.pop(0)
        if a == '--time':
            t = float(v)
        elif a == '--color':
            color = v
        else:
            normal = v
    else:
        args.append(a)
if len(args) != 2 or color not in ('landTime', 'height') \
        or normal not in ('x', 'y', 'z'):
    usage('wrong arguments')
series, png = args

reader = OpenDataFile(series)
times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
if t is None:
    t = times[-1]
view = GetActiveViewOrCreate('RenderView')
view.ViewTime = t
view.ViewSize = [1200, 900]
UpdatePipeline(t, reader)
names = reader.CellData.keys()
if 'matPatch' not in names:
    usage('no fiber in a mat at time %g in %s' % (t, series))

mat = Threshold(Input=reader, Scalars=['CELLS', 'matPatch'])
if hasattr(mat, 'LowerThreshold'):
    mat.LowerThreshold = 0
    mat.UpperThreshold = 1e9
else:
    mat.ThresholdRange = [0, 1e9]
UpdatePipeline(t, mat)
nSeg = sm.Fetch(mat).GetNumberOfCells()

pts = CellDatatoPointData(Input=ExtractSurface(Input=mat))
k = {'x': 0, 'y': 1, 'z': 2}[normal]
if color == 'height':
    bounds = sm.Fetch(mat).GetBounds()
    lo = bounds[2*k]
    field = Calculator(Input=pts)
    field.ResultArrayName = 'height'
    field.Function = '%s - %.17g' % (['coordsX', 'coordsY', 'coordsZ'][k], lo)
else:
    field = pts
tube = Tube(Input=field)
tube.Scalars = ['POINTS', 'diameter']
tube.VaryRadius = 'By Absolute Scalar'
tube.RadiusFactor = 0.5
tube.NumberofSides = 8
UpdatePipeline(t, tube)
disp = Show(tube, view)
ColorBy(disp, ('POINTS', color))
lut = GetColorTransferFunction(color)
lut.ApplyPreset('Viridis (matplotlib)', True)
disp.RescaleTransferFunctionToDataRange(True, False)
disp.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = 'joined the mat [s]' if color == 'landTime' else 'height [m]'
bar.ComponentTitle = ''
view.OrientationAxesVisibility = 1
b = sm.Fetch(tube).GetBounds()
c = [0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]), 0.5*(b[4] + b[5])]
eye = list(c)
eye[k] += 1.0
eye[(k + 1) % 3] -= 0.6
up = [0.0, 0.0, 0.0]
up[k] = 1.0
view.CameraPosition = eye
view.CameraFocalPoint = c
view.CameraViewUp = up
view.ResetCamera(False)
Render(view)
SaveScreenshot(png, view, ImageResolution=[1200, 900])
print('matView: %g %d %s' % (t, nSeg, png))
