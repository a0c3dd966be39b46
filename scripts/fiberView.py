# fiberTracking: read the fibers' VTK series with ParaView's own reader,
# report what is in it, and draw a picture.  Run with pvbatch (under
# xvfb-run where there is no display):
#   pvbatch scripts/fiberView.py <series> <times> <png> [case.foam]
# <times>: one time, or several separated by commas (drawn together, the
# later ones over the earlier).  Prints one line per time step of the
# series: time, segments (cells), fibers (distinct fiberId) and, per fiber,
# id and fiberVelocity of its first segment (lines 'fiber <t> <id> <vx>
# <vy> <vz>').  With case.foam, the picture shows the fibers over the
# case's walls cut by the mid-plane normal to x (its edges), each segment
# as a line glyph along the fiber, 2 % of the domain long, seen from the
# side; without it, the segments themselves.  Colour: |p_z|, the
# alignment with z (the diffuser's axis).
import sys
from paraview.simple import (OpenDataFile, Show, Render, GetActiveViewOrCreate,
                             ColorBy, SaveScreenshot, Outline, ResetCamera,
                             Glyph, CellCenters, Slice, FeatureEdges,
                             Calculator, ForceTime, GetColorTransferFunction,
                             ExtractSurface)
from paraview import servermanager as sm

series, png = sys.argv[1], sys.argv[3]
tPics = [float(t) for t in sys.argv[2].split(',')]
tPic = tPics[-1]
foam = sys.argv[4] if len(sys.argv) > 4 else None

reader = OpenDataFile(series)
times = list(reader.TimestepValues) if reader.TimestepValues else [tPic]
for t in times:
    reader.UpdatePipeline(t)
    data = sm.Fetch(reader)
    cd = data.GetCellData()
    ids = cd.GetArray('fiberId')
    vel = cd.GetArray('fiberVelocity')
    first = {}
    for c in range(data.GetNumberOfCells()):
        i = int(ids.GetValue(c))
        if i not in first:
            first[i] = vel.GetTuple3(c)
    print('step %.12g %d %d' % (t, data.GetNumberOfCells(), len(first)))
    for i in sorted(first):
        print('fiber %.12g %d %.17g %.17g %.17g' % ((t, i) + first[i]))

view = GetActiveViewOrCreate('RenderView')
view.ViewSize = [1000, 700]
view.ViewTime = tPic
if foam:
    # Fibers in a whole case are far smaller than the domain: each segment
    # is drawn as a line glyph along the fiber, 2 % of the domain long,
    # over the mesh outline, seen from the side (along -x)
    mesh = OpenDataFile(foam)
    mesh.UpdatePipeline()
    b = mesh.GetDataInformation().GetBounds()
    size = ((b[1] - b[0])**2 + (b[3] - b[2])**2 + (b[5] - b[4])**2)**0.5
    # The walls in the mid-plane: the edges of the mesh cut at x = centre
    cut = Slice(Input=mesh)
    cut.SliceType.Origin = [0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]),
                            0.5*(b[4] + b[5])]
    cut.SliceType.Normal = [1, 0, 0]
    edges = Show(FeatureEdges(Input=ExtractSurface(Input=cut)), view)
    ColorBy(edges, None)
    edges.AmbientColor = edges.DiffuseColor = [0, 0, 0]
    edges.LineWidth = 2
    lut = GetColorTransferFunction('alignment')
    for t in tPics:
        at = ForceTime(Input=reader)
        at.ForcedTime = t
        at.IgnorePipelineTime = 1
        align = Calculator(Input=CellCenters(Input=at))
        align.ResultArrayName = 'alignment'
        align.Function = 'abs(orientation_Z)'
        glyph = Glyph(Input=align, GlyphType='Line')
        glyph.OrientationArray = ['POINTS', 'orientation']
        glyph.ScaleArray = ['POINTS', 'No scale array']
        glyph.ScaleFactor = 0.02*size
        glyph.GlyphMode = 'All Points'
        shown = Show(glyph, view)
        shown.LineWidth = 2
        ColorBy(shown, ('POINTS', 'alignment'))
    lut.RescaleTransferFunction(0.0, 1.0)
    shown.SetScalarBarVisibility(view, True)
    view.CameraPosition = [b[1] + 2*size, 0.5*(b[2] + b[3]),
                           0.5*(b[4] + b[5])]
    view.CameraFocalPoint = [0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]),
                             0.5*(b[4] + b[5])]
    view.CameraViewUp = [0, 1, 0]
else:
    shown = Show(reader, view)
    shown.LineWidth = 3
    ColorBy(shown, ('CELLS', 'orientation', 'Z'))
    shown.RescaleTransferFunctionToDataRange(True)
ResetCamera(view)
Render(view)
SaveScreenshot(png, view, ImageResolution=[1000, 700])
print('png %s' % png)
