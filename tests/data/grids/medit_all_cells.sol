# A vector then a scalar per vertex: the scalar is x + 2y + 3z + 0.5 at each vertex.
MeshVersionFormatted 2
Dimension 3
Time
0.25
SolAtVertices
12
2 2 1
9 9 9   0.5
9 9 9   1.5
9 9 9   3.5
9 9 9   2.5
9 9 9   3.5
9 9 9   4.5
9 9 9   6.5
9 9 9   5.5
9 9 9   2.5
9 9 9   5.5
9 9 9   6.5
9 9 9   6.9
End
