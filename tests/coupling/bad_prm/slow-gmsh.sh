#!/bin/sh
# A gmsh that never finishes (PUMPD_GMSH for interrupt_meshing.sh): it writes its process id to
# $TMPDIR/gmsh.pid, says that it meshes, and sleeps.
echo $$ > "$TMPDIR/gmsh.pid"
echo "Info    : Meshing 2D..."
exec sleep 120
