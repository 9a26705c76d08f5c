#!/usr/bin/python3
"""Headless render of a run's last frame with VTK's Python (Debian's python3-vtk9, under
xvfb-run): the particles' surfaces coloured by coordination, the walls translucent, the contact
lines, written to a PNG; fails unless the picture shows the scene (over 3 % of the pixels away from
the background, over 20 distinct colours). Then the README's Tensor Glyph recipe on the particle
centres (default sphere of radius 0.5, eigenvalues extracted, Scale Factor 1): the glyph of each
ellipsoidal particle (exponents 2) must enclose its volume 4/3 pi a b c within 2 %.

  render_frame.py OUTPUT_DIR NAME PICTURE.png

(ParaView's own pvbatch cannot be installed next to libvtk9-dev on Debian 12: python3-paraview
conflicts with python3-vtk9, so this test renders through VTK itself.)"""
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkMassProperties, vtkTensorGlyph, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window's implementation)


def last_frame(directory, name, kind):
    collection = ElementTree.parse(os.path.join(directory, '%s_%s.pvd' % (name, kind)))
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(directory, collection.findall('.//DataSet')[-1].get('file')))
    reader.Update()
    return reader.GetOutput()


def actor(data, scalars=None, mode=None):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(data)
    if scalars:
        array = (data.GetPointData() if mode == 'points' else data.GetCellData()).GetArray(scalars)
        table = vtkLookupTable()
        table.SetHueRange(0.66, 0.0)
        table.Build()
        mapper.SetLookupTable(table)
        mapper.SetScalarModeToUsePointFieldData() if mode == 'points' else mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray(scalars)
        mapper.SetScalarRange(array.GetRange())
        mapper.ScalarVisibilityOn()
    else:
        mapper.ScalarVisibilityOff()
    a = vtkActor()
    a.SetMapper(mapper)
    return a


def render(directory, name, picture):
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    surfaces = last_frame(directory, name, 'surfaces')
    renderer.AddActor(actor(surfaces, 'coordination', 'points'))
    walls = actor(last_frame(directory, name, 'walls'))
    walls.GetProperty().SetOpacity(0.25)
    renderer.AddActor(walls)
    renderer.AddActor(actor(last_frame(directory, name, 'contacts'), 'normal_force', 'cells'))
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    x0, x1, y0, y1, z0, z1 = surfaces.GetBounds()
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)
    camera.SetPosition((x0 + x1) / 2 + 1.2 * (x1 - x0), (y0 + y1) / 2 - 2.0 * (y1 - y0), (z0 + z1) / 2 + (x1 - x0))
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera(surfaces.GetBounds())
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(picture)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    image = grab.GetOutput().GetPointData().GetScalars()  # RGB(A) bytes per pixel
    pixels = [image.GetTuple(i)[:3] for i in range(image.GetNumberOfTuples())]
    drawn = sum(p != (255.0, 255.0, 255.0) for p in pixels) / len(pixels)
    colours = len(set(pixels[::7]))
    print('%s: %d x %d, %.1f %% of the pixels drawn, %d colours' % (picture, 800, 600, 100 * drawn, colours))
    return drawn > 0.03 and colours > 20


def glyph_volume(tensor):
    """The volume of one Tensor Glyph (a reflected eigenvector frame turns the glyph inside out,
    so each glyph is measured alone)."""
    points, tensors = vtkPoints(), vtkDoubleArray()
    points.InsertNextPoint(0.0, 0.0, 0.0)
    tensors.SetNumberOfComponents(9)
    tensors.InsertNextTuple(tensor)
    centre = vtkPolyData()
    centre.SetPoints(points)
    centre.GetPointData().SetTensors(tensors)
    sphere = vtkSphereSource()  # ParaView's Tensor Glyph default: radius 0.5
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(64)
    glyph = vtkTensorGlyph()
    glyph.SetInputData(centre)
    glyph.SetSourceConnection(sphere.GetOutputPort())
    glyph.ExtractEigenvaluesOn()
    glyph.SetScaleFactor(1.0)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(glyph.GetOutputPort())
    mass = vtkMassProperties()
    mass.SetInputConnection(triangles.GetOutputPort())
    mass.Update()
    return mass.GetVolume()


def glyph_volumes(directory, name):
    particles = last_frame(directory, name, 'particles')
    data = particles.GetPointData()
    exponents, semi, tensors = data.GetArray('exponents'), data.GetArray('semi_axes'), data.GetArray('shape_tensor')
    worst, count = 0.0, 0
    for i in range(particles.GetNumberOfPoints()):
        if exponents.GetTuple(i) == (2.0, 2.0):
            a, b, c = semi.GetTuple(i)
            expected = 4.0 / 3.0 * math.pi * a * b * c
            worst = max(worst, abs(glyph_volume(tensors.GetTuple(i)) / expected - 1.0))
            count += 1
    print('Tensor Glyph at Scale Factor 1: %d ellipsoids, glyph volumes within %.2f %% of the particles\'' % (count, 100 * worst))
    return count > 0 and worst < 0.02


def main():
    directory, name, picture = sys.argv[1:4]
    ok = render(directory, name, picture)
    ok = glyph_volumes(directory, name) and ok
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
