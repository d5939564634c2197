#!/usr/bin/env python3
"""The peer of facet's marching cubes: VTK's flying edges and marching cubes
filters on the same Marschner-Lobb volume (the formula of
renderer/volume/load_volume.h, in double, stored as float) at the same iso
value, timed in this process. Prints one line per filter:
    vtk <filter>: <triangles> triangles in <ms> ms (median of <runs>)
Needs Debian's python3-vtk9 and python3-numpy (scripts/bench-volumes.sh)."""
import statistics
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D, vtkMarchingCubes


def marschner_lobb(n):
    axis = np.linspace(-1.0, 1.0, n)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")  # x fastest in memory, as facet stores it
    alpha, f_m = 0.25, 6.0
    r = np.sqrt(x * x + y * y)
    rho_r = np.cos(2.0 * np.pi * f_m * np.cos(np.pi * r / 2.0))
    return ((1.0 - np.sin(np.pi * z / 2.0) + alpha * (1.0 + rho_r)) / (2.0 * (1.0 + alpha))).astype(np.float32)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 256
    iso = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    values = marschner_lobb(n)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1))
    image.GetPointData().SetScalars(numpy_to_vtk(values.ravel(), deep=True))
    for name, make in (("flying edges", vtkFlyingEdges3D), ("marching cubes", vtkMarchingCubes)):
        times, triangles = [], 0
        for _ in range(runs):
            f = make()
            f.SetInputData(image)
            f.SetValue(0, iso)
            f.ComputeNormalsOn()  # facet's mesh carries gradient normals too
            start = time.perf_counter()
            f.Update()
            times.append(1000.0 * (time.perf_counter() - start))
            triangles = f.GetOutput().GetNumberOfPolys()
        print("vtk %s: %d triangles in %.2f ms (median of %d)" % (name, triangles, statistics.median(times), runs))


if __name__ == "__main__":
    main()
