#!/usr/bin/python3
"""A PNG of a mesh rendered offscreen with VTK: its surface with the element edges drawn,
coloured by a point-data array when one is named (e.g. a field written by adapt --transfer).

Needs a display: on a machine without one, run it under xvfb-run.
usage: render_mesh.py MESH.vtu OUT.png [--array NAME] [--view top|iso] [--size W H] [--zoom Z] [--focus X Y Z]
                      [--colors N]   (a palette of N colours, with PIL: a smaller file)
"""
import argparse

import vtk


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesh")
    ap.add_argument("png")
    ap.add_argument("--array", help="point-data array to colour by (its magnitude)")
    ap.add_argument("--view", choices=["top", "iso"], default="iso")
    ap.add_argument("--size", type=int, nargs=2, default=[1200, 800])
    ap.add_argument("--zoom", type=float, default=1.0)
    ap.add_argument("--focus", type=float, nargs=3, help="look at this point (default: the mesh's centre)")
    ap.add_argument("--colors", type=int, default=0, help="reduce the PNG to a palette of this many colours (PIL)")
    a = ap.parse_args()

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(a.mesh)
    reader.Update()
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(reader.GetOutputPort())
    surface.Update()

    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    if a.array:
        data = reader.GetOutput().GetPointData().GetArray(a.array)
        if data is None:
            raise SystemExit(f"{a.mesh}: no point data {a.array}")
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(a.array)
        mapper.ColorByArrayComponent(a.array, -1)
        mapper.SetScalarRange(data.GetRange(-1))
        lut = vtk.vtkLookupTable()
        lut.SetHueRange(0.667, 0.0)
        lut.SetVectorModeToMagnitude()
        lut.Build()
        mapper.SetLookupTable(lut)
    else:
        mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(0.85, 0.88, 0.92)
    prop.EdgeVisibilityOn()
    prop.SetEdgeColor(0.1, 0.1, 0.25)
    prop.SetLineWidth(0.6)

    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1, 1, 1)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*a.size)
    camera = renderer.GetActiveCamera()
    if a.view == "top":
        camera.SetPosition(0, 0, 1)
        camera.SetViewUp(0, 1, 0)
    else:
        camera.SetPosition(1, -1.6, 1.4)
        camera.SetViewUp(0, 0, 1)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCamera()
    if a.focus:
        shift = [f - c for f, c in zip(a.focus, camera.GetFocalPoint())]
        camera.SetFocalPoint(*a.focus)
        camera.SetPosition(*[p + s for p, s in zip(camera.GetPosition(), shift)])
    camera.Zoom(a.zoom)
    window.Render()

    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(a.png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if a.colors:
        from PIL import Image
        Image.open(a.png).convert("P", palette=Image.ADAPTIVE, colors=a.colors).save(a.png, optimize=True)


if __name__ == "__main__":
    main()
