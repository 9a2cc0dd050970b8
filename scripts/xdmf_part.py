# SPDX-License-Identifier: BSD-2-Clause
"""ParaView 5.11's XDMF reader leaves the parts of a spatial collection unnamed, so the render
scripts read each part from a copy of the series that holds only it."""
import xml.etree.ElementTree as ET


def part_copy(path, name):
    """A copy of the series `path` (absolute) with only the part `name` in each frame, written
    beside it as <stem>.<name>.xdmf; the caller removes it."""
    tree = ET.parse(path)
    for frame in tree.getroot().iter("Grid"):
        if frame.get("CollectionType") == "Spatial":
            for grid in list(frame.findall("Grid")):
                if grid.get("Name") != name:
                    frame.remove(grid)
    copy = f"{path[:-5]}.{name}.xdmf"
    tree.write(copy)
    return copy
