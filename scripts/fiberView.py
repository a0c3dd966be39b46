# fiberTracking: read the fibers' VTK series with ParaView's own reader,
# report what is in it, and draw a picture.  Run with pvbatch (under
# xvfb-run where there is no display):
#   pvbatch scripts/fiberView.py <series> <times> <png> [case.foam]
#           [--flow <dx>,<dy>,<dz> | --flow none] [--normal x|y|z]
# <times>: one time, or several separated by commas (drawn together, the
# later ones over the earlier).  Prints one line per time step of the
# series: time, segments (cells), fibers (distinct fiberId) and, per fiber,
# id and fiberVelocity of its first segment (lines 'fiber <t> <id> <vx>
# <vy> <vz>').  With case.foam, the picture shows the fibers over the
# outline of the case's walls (its patches of type wall, cut by the
# mid-plane normal to x, or to --normal's axis), seen along that normal in
# parallel projection (normal x: z to the right, y up; y: x right, z up;
# z: x right, y up), each segment as a line glyph along the fiber, 2 % of
# the domain long, and an arrow labelled 'flow' above them along the mean
# flow direction: from the centre of the patches named *inlet* to that of
# the patches named *outlet*, or the direction given with --flow ('--flow
# none': no arrow).  Without case.foam, the segments themselves.  Colour:
# |p_z|, the alignment with z (the diffuser's axis), with a colour legend.
import math
import os
import re
import sys
from paraview.simple import (OpenDataFile, Show, Render, GetActiveViewOrCreate,
                             ColorBy, SaveScreenshot, ResetCamera, Glyph,
                             CellCenters, Slice, Calculator, ForceTime,
                             GetColorTransferFunction, GetScalarBar,
                             ExtractSurface, PointSource, Transform, a3DText)
from paraview import servermanager as sm


def usage(msg):
    sys.stderr.write('fiberView.py: %s\nusage: pvbatch fiberView.py <series> '
                     '<times> <png> [case.foam] [--flow dx,dy,dz | --flow '
                     'none] [--normal x|y|z]\n' % msg)
    sys.exit(1)


args, flowArg, normalArg = [], None, 'x'
argv = sys.argv[1:]
while argv:
    a = argv.pop(0)
    if a in ('-flow', '--flow'):
        if not argv:
            usage('option --flow needs an argument')
        flowArg = argv.pop(0)
    elif a in ('-normal', '--normal'):
        if not argv or argv[0] not in ('x', 'y', 'z'):
            usage('option --normal needs x, y or z')
        normalArg = argv.pop(0)
    else:
        args.append(a)
if len(args) not in (3, 4):
    usage('wrong number of arguments')
series, png = args[0], args[2]
tPics = [float(t) for t in args[1].split(',')]
tPic = tPics[-1]
foam = args[3] if len(args) > 3 else None

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


def patchTypes(caseFile):
    """Name and type of the case's patches, from constant/polyMesh/boundary
    (or processor0's in a decomposed case), in their order"""
    case = os.path.dirname(os.path.abspath(caseFile))
    for d in ('constant', 'processor0/constant'):
        f = os.path.join(case, d, 'polyMesh', 'boundary')
        if os.path.isfile(f):
            text = open(f).read()
            text = re.sub(r'//.*', '', re.sub(r'/\*.*?\*/', '', text,
                                              flags=re.S))
            text = text[text.find('(', text.find('}') + 1):]
            return [(m.group(1), re.search(r'\btype\s+(\w+)\s*;',
                                           m.group(2)).group(1))
                    for m in re.finditer(r'([^\s{}()]+)\s*\{([^}]*)\}', text)
                    if re.search(r'\btype\s+(\w+)\s*;', m.group(2))]
    return []


def openPatches(names):
    """The case's patches 'names' (no internal mesh, no fields)"""
    r = OpenDataFile(foam)
    known = r.GetProperty('MeshRegions').Available   # 'patch/<name>' (5.10 on)
    r.MeshRegions = [('patch/' + n) if ('patch/' + n) in known else n
                     for n in names]
    r.CellArrays = []
    r.UpdatePipeline()
    return r


def centre(names):
    """Centre of the bounding box of the patches 'names'"""
    bb = openPatches(names).GetDataInformation().GetBounds()
    return [0.5*(bb[0] + bb[1]), 0.5*(bb[2] + bb[3]), 0.5*(bb[4] + bb[5])]


view = GetActiveViewOrCreate('RenderView')
view.ViewSize = [1000, 700]
view.ViewTime = tPic
if foam:
    # Fibers in a whole case are far smaller than the domain: each segment
    # is drawn as a line glyph along the fiber, 2 % of the domain long,
    # over the walls' outline in the mid-plane, seen along its normal
    patches = patchTypes(foam)
    walls = [n for n, t in patches if t == 'wall']
    if not walls:
        # no patch of type wall: the outline of all the physical patches
        walls = [n for n, t in patches if t not in
                 ('empty', 'cyclic', 'cyclicAMI', 'cyclicACMI', 'processor',
                  'processorCyclic', 'symmetry', 'symmetryPlane', 'wedge')]
    if walls:
        mesh = openPatches(walls)
    else:
        # no boundary file: the whole mesh
        mesh = OpenDataFile(foam)
        mesh.MeshRegions = ['internalMesh']
        mesh.CellArrays = []
        mesh.UpdatePipeline()
    b = mesh.GetDataInformation().GetBounds()
    size = ((b[1] - b[0])**2 + (b[3] - b[2])**2 + (b[5] - b[4])**2)**0.5
    mid = [0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]), 0.5*(b[4] + b[5])]
    # The picture's axes: the cut's normal, and which coordinates are
    # right and up on the screen; the camera side; the rotation that puts
    # text (written in x-y, facing +z) in the picture's plane
    n, r, u, side, rotate = {'x': (0, 2, 1, -1, [0, -90, 0]),
                             'y': (1, 0, 2, -1, [90, 0, 0]),
                             'z': (2, 0, 1, 1, [0, 0, 0])}[normalArg]

    def point(right, up):
        """The point of the mid-plane at these screen coordinates"""
        q = [0.0, 0.0, 0.0]
        q[n], q[r], q[u] = mid[n], right, up
        return q

    # The walls in the mid-plane: the wall patches (surfaces) cut by the
    # plane through the middle, which gives their lines only (a cut of the
    # volume mesh also drew the edges of the cut's polygons where internal
    # faces lie in the plane: stray lines)
    cut = Slice(Input=ExtractSurface(Input=mesh))
    cut.SliceType = 'Plane'
    cut.SliceType.Origin = mid
    cut.SliceType.Normal = [1 if k == n else 0 for k in range(3)]
    cut.Triangulatetheslice = 0
    edges = Show(cut, view)
    edges.ColorArrayName = ['POINTS', '']
    edges.AmbientColor = edges.DiffuseColor = [0, 0, 0]
    edges.LineWidth = 2.5
    cut.UpdatePipeline(tPic)
    drawn = [cut.GetDataInformation().GetBounds()]
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
        glyph.UpdatePipeline(tPic)
        drawn.append(glyph.GetDataInformation().GetBounds())
    lut.RescaleTransferFunction(0.0, 1.0)
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = r'alignment $\vert p_z\vert$'
    bar.ComponentTitle = ''
    bar.Orientation = 'Horizontal'
    bar.WindowLocation = 'Lower Center'
    bar.ScalarBarLength = 0.4
    bar.RangeLabelFormat = '%-#.1f'

    # The extent of what is drawn, (right, up) on the screen
    drawn = [d for d in drawn if d[0] <= d[1]]
    if not drawn:
        drawn = [b]
    lo = [min(d[2*r] for d in drawn), min(d[2*u] for d in drawn)]
    hi = [max(d[2*r + 1] for d in drawn), max(d[2*u + 1] for d in drawn)]
    width, height = hi[0] - lo[0], hi[1] - lo[1]
    # The mean flow direction: inlet(s) -> outlet(s), or --flow
    flow = None
    if flowArg is not None and flowArg != 'none':
        try:
            flow = [float(v) for v in flowArg.split(',')]
        except ValueError:
            usage("--flow: '%s' is not dx,dy,dz" % flowArg)
        if len(flow) != 3:
            usage("--flow: '%s' is not dx,dy,dz" % flowArg)
    elif flowArg is None:
        ins = [p for p, t in patches if 'inlet' in p.lower()]
        outs = [p for p, t in patches if 'outlet' in p.lower()]
        if ins and outs:
            ci, co = centre(ins), centre(outs)
            flow = [co[k] - ci[k] for k in range(3)]
    if flow:
        # its projection on the picture
        fr, fu = flow[r], flow[u]
        norm = math.hypot(fr, fu)
        if norm <= 0.1*math.sqrt(sum(f*f for f in flow)):
            print('flow %.6g %.6g %.6g: along the view, no arrow'
                  % tuple(flow))
            flow = None
    if flow:
        fr, fu = fr/norm, fu/norm
        print('flow %.6g %.6g %.6g' % tuple(flow))
        # An arrow above the drawing, a quarter of its width long, its
        # middle over the middle of the drawing, and the label over it
        length = 0.25*max(width, height)
        gap = 0.08*max(height, 0.25*width) + 0.08*length
        c = [0.5*(lo[0] + hi[0]), hi[1] + gap + 0.5*length*abs(fu)]
        start = PointSource(NumberOfPoints=1, Radius=0,
                            Center=point(c[0] - 0.5*length*fr,
                                         c[1] - 0.5*length*fu))
        dirn = Calculator(Input=start)
        dirn.ResultArrayName = 'flow'
        e = point(fr, fu)
        e[n] = 0.0
        dirn.Function = '%.17g*iHat + %.17g*jHat + %.17g*kHat' % tuple(e)
        arrow = Glyph(Input=dirn, GlyphType='Arrow')
        arrow.OrientationArray = ['POINTS', 'flow']
        arrow.ScaleArray = ['POINTS', 'No scale array']
        arrow.ScaleFactor = length
        arrow.GlyphMode = 'All Points'
        arrow.GlyphType.TipRadius = 0.08
        arrow.GlyphType.TipLength = 0.25
        arrow.GlyphType.ShaftRadius = 0.025
        arrow.GlyphType.TipResolution = arrow.GlyphType.ShaftResolution = 24
        shownArrow = Show(arrow, view)
        shownArrow.ColorArrayName = ['POINTS', '']
        shownArrow.AmbientColor = shownArrow.DiffuseColor = [0.05, 0.05, 0.05]
        shownArrow.Ambient = 0.4
        # 'flow' in 3-D letters in the plane of the picture (vtkVectorText:
        # letters about 1 high), centred over the arrow
        h = 0.03*max(width, height)
        text = a3DText(Text='flow')
        text.UpdatePipeline()
        tb = text.GetDataInformation().GetBounds()
        tw = (tb[1] - tb[0])*h
        base = c[1] + 0.5*length*abs(fu) + 0.08*length + 0.4*h
        place = Transform(Input=text)
        place.Transform = 'Transform'
        place.Transform.Scale = [h, h, h]
        place.Transform.Rotate = rotate
        place.Transform.Translate = point(c[0] - 0.5*tw - tb[0]*h,
                                          base - tb[2]*h)
        shownText = Show(place, view)
        shownText.ColorArrayName = ['POINTS', '']
        shownText.AmbientColor = shownText.DiffuseColor = [0.05, 0.05, 0.05]
        shownText.Ambient = 1.0
        shownText.Diffuse = 0.0
        hi[1] = max(hi[1], base + (tb[3] - tb[2])*h)
        lo[0] = min(lo[0], c[0] - 0.5*length*abs(fr) - 0.1*length,
                    c[0] - 0.5*tw)
        hi[0] = max(hi[0], c[0] + 0.5*length*abs(fr) + 0.1*length,
                    c[0] + 0.5*tw)

    # Parallel projection, the drawing filling the picture above the
    # colour legend (after a first render: ParaView resets the camera at
    # the first one)
    Render(view)
    view.CameraParallelProjection = 1
    view.CameraViewUp = [1 if k == u else 0 for k in range(3)]
    aspect = 1000.0/700.0
    w, h = hi[0] - lo[0], hi[1] - lo[1]
    scale = 1.08*max(0.5*h/0.78, 0.5*w/aspect, 1e-3*size)
    # the drawing's centre 0.1 of the picture's height above its middle
    focus = point(0.5*(lo[0] + hi[0]), 0.5*(lo[1] + hi[1]) - 0.2*scale)
    view.CameraFocalPoint = focus
    eye = list(focus)
    eye[n] += side*2*size
    view.CameraPosition = eye
    view.CameraParallelScale = scale
else:
    shown = Show(reader, view)
    shown.LineWidth = 3
    ColorBy(shown, ('CELLS', 'orientation', 'Z'))
    shown.RescaleTransferFunctionToDataRange(True)
    shown.SetScalarBarVisibility(view, True)
    ResetCamera(view)
Render(view)
SaveScreenshot(png, view, ImageResolution=[1000, 700])
print('png %s' % png)
