# Writes the vtk_mixed_* and vtu_mixed_* test grids with VTK's own writers (Debian's
# python3-vtk9, VTK 9.1): run with /usr/bin/python3 from this folder. One grid of 17 points and
# 7 cells: a hexahedron, a tetrahedron, a triangle, a voxel, a wedge, a pyramid and a vertex.
import vtk

points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1),
          (0.5, 0.5, 2)]
points += [(2 + x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]  # the voxel's, x fastest
cells = [(12, [0, 1, 2, 3, 4, 5, 6, 7]), (10, [4, 5, 6, 8]), (5, [0, 1, 2]),
         (11, list(range(9, 17))), (13, [0, 1, 3, 4, 5, 7]), (14, [4, 5, 6, 7, 8]), (1, [8])]

grid = vtk.vtkUnstructuredGrid()
vtk_points = vtk.vtkPoints()
vtk_points.SetDataTypeToDouble()
for p in points:
    vtk_points.InsertNextPoint(p)
grid.SetPoints(vtk_points)
for cell_type, corners in cells:
    grid.InsertNextCell(cell_type, len(corners), corners)

temperature = vtk.vtkFloatArray()
temperature.SetName("temperature")
velocity = vtk.vtkDoubleArray()
velocity.SetName("velocity")
velocity.SetNumberOfComponents(3)
velocity.SetComponentName(0, "vx")  # makes the legacy writer add a METADATA block
pressure = vtk.vtkIntArray()
pressure.SetName("pressure")
for i in range(len(points)):
    temperature.InsertNextValue(0.5 * i)
    velocity.InsertNextTuple3(-i, 2 * i, 3 * i)
    pressure.InsertNextValue(100 + i)
grid.GetPointData().SetScalars(temperature)
grid.GetPointData().SetVectors(velocity)
grid.GetPointData().AddArray(pressure)  # a FIELD array in legacy files
material = vtk.vtkIntArray()
material.SetName("material")
quality = vtk.vtkDoubleArray()
quality.SetName("quality")
for i in range(len(cells)):
    material.InsertNextValue(i + 1)
    quality.InsertNextValue(i / 10)
grid.GetCellData().SetScalars(material)
grid.GetCellData().AddArray(quality)

legacy = vtk.vtkUnstructuredGridWriter()
legacy.SetInputData(grid)
for version, suffix in ((51, "51"), (42, "42")):
    legacy.SetFileVersion(version)
    for binary in (False, True):
        legacy.SetFileName("vtk_mixed_%s_%s.vtk" % (suffix, "binary" if binary else "ascii"))
        if binary:
            legacy.SetFileTypeToBinary()
        else:
            legacy.SetFileTypeToASCII()
        legacy.Write()

def write_vtu(name, mode, compressed=False, header64=False, big_endian=False, encode=True):
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetInputData(grid)
    writer.SetFileName(name)
    {"ascii": writer.SetDataModeToAscii, "binary": writer.SetDataModeToBinary,
     "appended": writer.SetDataModeToAppended}[mode]()
    if compressed:
        writer.SetCompressorTypeToZLib()
    else:
        writer.SetCompressorTypeToNone()
    if header64:
        writer.SetHeaderTypeToUInt64()
    if big_endian:
        writer.SetByteOrderToBigEndian()
    writer.SetEncodeAppendedData(encode)
    writer.Write()

write_vtu("vtu_mixed_ascii.vtu", "ascii")
write_vtu("vtu_mixed_binary.vtu", "binary")
write_vtu("vtu_mixed_binary_uint64.vtu", "binary", header64=True)
write_vtu("vtu_mixed_binary_zlib.vtu", "binary", compressed=True)
write_vtu("vtu_mixed_appended_raw.vtu", "appended", encode=False)
write_vtu("vtu_mixed_appended_base64.vtu", "appended", encode=True)
write_vtu("vtu_mixed_appended_raw_zlib_uint64.vtu", "appended", compressed=True, header64=True,
          encode=False)
write_vtu("vtu_mixed_big_endian_zlib.vtu", "binary", compressed=True, big_endian=True)
write_vtu("vtu_mixed_appended_raw_big_endian.vtu", "appended", big_endian=True, encode=False)
