# fiberTracking: the fibers of a run with contacts in 3-D, coloured by the
# floc they belong to.  Run with pvbatch (under xvfb-run where there is no
# display):
#   pvbatch scripts/flocView.py <series> <time|last> <png> [case.foam]
#           [--title <text>] [--top <K>] [--thick <f>]
# <series>: the fibers' VTK series (postProcessing/<name>/<t>/vtk/
# <name>.vtp.series) of a run with 'interactions { type contact; }' (cell
# array flocId); <time>: the output time to draw (the nearest in the
# series; 'last': the last one).  Prints 'step <time> <segments> <fibers>
# <flocs> <largest> <fibersInFlocs>' and the K largest flocs ('floc <rank>
# <flocId> <fibers>').  Draws each segment as a tube f times the fiber's
# diameter thick (default 1.5, 1 above 1000 fibers): the K largest flocs
# (default 10) each in its own colour, the other flocs in mid grey, the
# fibers in no floc in light grey, with a legend (fibers per floc), in the
# outline of the case's mesh (with case.foam: the periodic box) or of the
# fibers' bounds, seen obliquely (x to the right, y up, z towards the
# viewer), on white, 1000 x 800, with a title (<text>, default the
# series' name) and a line of numbers (time, fibers, flocs, the largest,
# share in flocs).  With Python's PIL the PNG is stored with a palette of
# the colours drawn (a third of the size).
import sys
from paraview.simple import (OpenDataFile, Show, Render, GetActiveViewOrCreate,
                             ColorBy, SaveScreenshot, Outline, Tube,
                             PVTrivialProducer, Text, ForceTime,
                             GetColorTransferFunction, GetScalarBar)
from paraview import servermanager as sm
from vtkmodules.vtkCommonCore import vtkIntArray


def usage(msg):
    sys.stderr.write('flocView.py: %s\nusage: pvbatch flocView.py <series> '
                     '<time|last> <png> [case.foam] [--title text] '
                     '[--top K] [--thick f]\n' % msg)
    sys.exit(1)


args, title, top, thick = [], None, 10, None
argv = sys.argv[1:]
while argv:
    a = argv.pop(0)
    if a in ('-title', '--title', '-top', '--top', '-thick', '--thick'):
        if not argv:
            usage('option %s needs an argument' % a)
        v = argv.pop(0)
        try:
            if a.endswith('title'):
                title = v
            elif a.endswith('top'):
                top = int(v)
            else:
                thick = float(v)
        except ValueError:
            usage("option %s: invalid value '%s'" % (a, v))
    else:
        args.append(a)
if len(args) not in (3, 4) or top < 1 or (thick is not None and thick <= 0):
    usage('wrong arguments')
series, tArg, png = args[0], args[1], args[2]
foam = args[3] if len(args) > 3 else None

reader = OpenDataFile(series)
times = list(reader.TimestepValues) if reader.TimestepValues else []
if tArg == 'last':
    if not times:
        usage('no time steps in %s' % series)
    t = times[-1]
else:
    try:
        t = float(tArg)
    except ValueError:
        usage("invalid time '%s'" % tArg)
    if times:
        # the output time nearest to the one asked for
        t = min(times, key=lambda s: abs(s - t))
at = ForceTime(Input=reader)
at.ForcedTime = t
at.IgnorePipelineTime = 1
at.UpdatePipeline(t)

# The flocs at that time: fibers (distinct fiberId) per flocId, ranked by
# size (ties: lower flocId first)
data = sm.Fetch(at)
cd = data.GetCellData()
if cd.GetArray('flocId') is None:
    usage('no flocId in %s (a run without contacts?)' % series)
fiberOf = cd.GetArray('fiberId')
flocOf = cd.GetArray('flocId')
members = {}
fibers = set()
for c in range(data.GetNumberOfCells()):
    i, f = int(fiberOf.GetValue(c)), int(flocOf.GetValue(c))
    fibers.add(i)
    if f >= 0:
        members.setdefault(f, set()).add(i)
ranked = sorted(members, key=lambda f: (-len(members[f]), f))
inFlocs = sum(len(m) for m in members.values())
largest = len(members[ranked[0]]) if ranked else 0
print('step %.12g %d %d %d %d %d' % (t, data.GetNumberOfCells(), len(fibers),
                                     len(ranked), largest, inFlocs))
nTop = min(top, len(ranked))
for k in range(nTop):
    print('floc %d %d %d' % (k, ranked[k], len(members[ranked[k]])))
rank = dict((f, k) for k, f in enumerate(ranked))

# The cell array 'floc': the rank of the fiber's floc for the K largest,
# K for any other floc, -1 for none; the fibers with it into the pipeline
flocArray = vtkIntArray()
flocArray.SetName('floc')
flocArray.SetNumberOfTuples(data.GetNumberOfCells())
for c in range(data.GetNumberOfCells()):
    f = int(flocOf.GetValue(c))
    flocArray.SetValue(c, -1 if f < 0 else min(rank[f], nTop))
cd.AddArray(flocArray)
flocRank = PVTrivialProducer()
flocRank.GetClientSideObject().SetOutput(data)
flocRank.UpdatePipeline()

view = GetActiveViewOrCreate('RenderView')
view.ViewSize = [1000, 800]
view.ViewTime = t
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesLabelColor = [0, 0, 0]
view.OrientationAxesVisibility = 1

# Tubes along the segments, thick f times the fiber's diameter (default
# 1.5, 1 in crowds of more than 1000 fibers)
if thick is None:
    thick = 1.5 if len(fibers) <= 1000 else 1.0
diameter = cd.GetArray('diameter').GetRange()[1] if \
    cd.GetArray('diameter') else 0.0
b = data.GetBounds()
size = ((b[1] - b[0])**2 + (b[3] - b[2])**2 + (b[5] - b[4])**2)**0.5
tubes = Tube(Input=flocRank)
tubes.Scalars = ['POINTS', '']
tubes.Vectors = ['POINTS', '']
tubes.Radius = 0.5*thick*diameter if diameter > 0 else 2e-3*size
tubes.NumberofSides = 10
tubes.Capping = 1
shown = Show(tubes, view)
ColorBy(shown, ('CELLS', 'floc'))
shown.Specular = 0.3
shown.SpecularPower = 40

# Categorical colours: the K largest flocs (Tableau 10, then ten from
# ColorBrewer's Dark 2 and Set 1 for K > 10, then again), the other flocs
# mid grey, no floc light grey
palette = [
    [0.122, 0.467, 0.706], [1.000, 0.498, 0.055], [0.173, 0.627, 0.173],
    [0.839, 0.153, 0.157], [0.580, 0.404, 0.741], [0.549, 0.337, 0.294],
    [0.890, 0.467, 0.761], [0.737, 0.741, 0.133], [0.090, 0.745, 0.812],
    [0.984, 0.604, 0.600],
    [0.106, 0.620, 0.467], [0.851, 0.373, 0.008], [0.459, 0.439, 0.702],
    [0.906, 0.161, 0.541], [0.400, 0.651, 0.118], [0.902, 0.671, 0.008],
    [0.651, 0.463, 0.114], [0.894, 0.102, 0.110], [0.216, 0.494, 0.722],
    [0.302, 0.686, 0.290]]
lut = GetColorTransferFunction('floc')
lut.InterpretValuesAsCategories = 1
lut.AnnotationsInitialized = 1
annotations, colours = ['-1', 'no floc'], [0.85, 0.85, 0.85]
for k in range(nTop):
    annotations += [str(k), '%d fibers' % len(members[ranked[k]])]
    colours += palette[k % len(palette)]
if len(ranked) > nTop:
    sizes = [len(members[f]) for f in ranked[nTop:]]
    annotations += [str(nTop), '%d more flocs, %d-%d fibers'
                    % (len(sizes), min(sizes), max(sizes))
                    if min(sizes) != max(sizes) else
                    '%d more flocs, %d fibers' % (len(sizes), sizes[0])]
    colours += [0.5, 0.5, 0.5]
lut.Annotations = annotations
lut.IndexedColors = colours
shown.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = 'flocs'
bar.ComponentTitle = ''
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.TitleFontSize = 18
bar.LabelFontSize = 15
bar.WindowLocation = 'Any Location'
bar.ScalarBarLength = min(0.6, 0.05*len(annotations)/2)
bar.Position = [0.82, 0.72 - bar.ScalarBarLength]

# The box: the case's mesh (the periodic box), or the fibers' bounds
if foam:
    mesh = OpenDataFile(foam)
    mesh.MeshRegions = ['internalMesh']
    mesh.CellArrays = []
    box = Outline(Input=mesh)
else:
    box = Outline(Input=at)
shownBox = Show(box, view)
shownBox.ColorArrayName = ['POINTS', '']
shownBox.AmbientColor = shownBox.DiffuseColor = [0, 0, 0]
shownBox.LineWidth = 2
box.UpdatePipeline(t)
bb = box.GetDataInformation().GetBounds()

# Title and numbers at the top
name = title if title is not None else \
    series.split('/')[-1].replace('.vtp.series', '')
head = Text(Text=name)
shownHead = Show(head, view)
shownHead.WindowLocation = 'Upper Left Corner'
shownHead.FontSize = 22
shownHead.Color = [0, 0, 0]
if ranked:
    numbers = ('t = %.4g s: %d fibers, %d floc%s, the largest %d fibers, '
               '%.3g %% of the fibers in flocs'
               % (t, len(fibers), len(ranked),
                  '' if len(ranked) == 1 else 's', largest,
                  100.0*inFlocs/max(1, len(fibers))))
else:
    numbers = 't = %.4g s: %d fibers, no flocs' % (t, len(fibers))
info = Text(Text=numbers)
shownInfo = Show(info, view)
shownInfo.WindowLocation = 'Any Location'
shownInfo.Position = [0.01, 0.905]
shownInfo.FontSize = 15
shownInfo.Color = [0.1, 0.1, 0.1]

# An oblique view of the box, a little from above and the right, the box
# left of the legend (the focal point right of the box's centre)
Render(view)
centre = [0.5*(bb[0] + bb[1]), 0.5*(bb[2] + bb[3]), 0.5*(bb[4] + bb[5])]
diag = ((bb[1] - bb[0])**2 + (bb[3] - bb[2])**2 + (bb[5] - bb[4])**2)**0.5
direction = [0.55, 0.45, 1.0]
norm = sum(d*d for d in direction)**0.5
direction = [d/norm for d in direction]
up = [0, 1, 0]
right = [up[1]*direction[2] - up[2]*direction[1],
         up[2]*direction[0] - up[0]*direction[2],
         up[0]*direction[1] - up[1]*direction[0]]
norm = sum(d*d for d in right)**0.5
right = [d/norm for d in right]
focus = [centre[k] + 0.14*diag*right[k] - 0.03*diag*up[k] for k in range(3)]
view.CameraFocalPoint = focus
view.CameraPosition = [focus[k] + 2.45*diag*direction[k] for k in range(3)]
view.CameraViewUp = up
view.CameraViewAngle = 30
view.CameraParallelProjection = 0
Render(view)
SaveScreenshot(png, view, ImageResolution=[1000, 800],
               CompressionLevel='9')

# A smaller file: the picture in a palette of the colours drawn, greys and
# shades and tints of the floc colours (a third of the size, the same
# look), where Python's PIL is there (and K <= 16: 256 colours)
try:
    from PIL import Image
except ImportError:
    Image = None
if Image is not None and nTop <= 16:
    shades = [[g/31.0]*3 for g in range(32)]
    for rgb in palette[:nTop]:
        shades += [[s*v for v in rgb] for s in
                   (0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0)]
        shades += [[v + (1 - v)*s for v in rgb] for s in (0.2, 0.4, 0.6, 0.8)]
    for rgb in ([1, 0, 0], [1, 1, 0], [0, 1, 0]):     # orientation axes
        shades += [[s*v for v in rgb] for s in (0.4, 0.7, 1.0)]
    flat = [int(round(255*v)) for rgb in shades for v in rgb]
    pal = Image.new('P', (1, 1))
    pal.putpalette(flat + [0]*(768 - len(flat)))
    Image.open(png).convert('RGB').quantize(
        palette=pal, dither=getattr(Image, 'Dither', Image).NONE).save(
            png, optimize=True)
print('png %s' % png)
