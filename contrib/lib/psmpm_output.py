"""Readers of psmpm's output files, shared by the scripts of contrib/.

    import os, sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    "..", "..", "lib"))   # from contrib/<a>/<b>/
    from psmpm_output import ROOT, vtu_arrays, read_statistics, read_summary

ROOT is the source tree (the parent of contrib/). Needs python3-numpy
(Debian); the scripts run with /usr/bin/python3.
"""
import base64
import json
import os
import re
import struct
import zlib

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

_VTU_TYPES = {'Float32': '<f4', 'Float64': '<f8', 'Int32': '<i4',
              'UInt8': 'u1'}


def vtu_arrays(path):
    """name -> numpy array (float) of a deal.II zlib-compressed binary VTU
    file: the point coordinates as "Points" (n x 3), every DataArray by its
    Name, one row per point for vector and tensor fields."""
    text = open(path).read()
    out = {}
    for m in re.finditer(r'<DataArray([^>]*)>\s*([^<]*)</DataArray>', text):
        attrs, data = m.group(1), m.group(2).strip()
        name = re.search(r'Name="([^"]*)"', attrs)
        name = name.group(1) if name else "Points"
        typ = re.search(r'type="([^"]*)"', attrs).group(1)
        ncomp = re.search(r'NumberOfComponents="(\d+)"', attrs)
        ncomp = int(ncomp.group(1)) if ncomp else 1
        # deal.II's header: number of blocks, block size, last block size,
        # then the compressed size of each block, as UInt32, base64.
        nb = struct.unpack('<I', base64.b64decode(data[:8] + '====')[:4])[0]
        hbytes = (3 + nb) * 4
        hlen = (hbytes + 2) // 3 * 4
        header = struct.unpack('<%dI' % (3 + nb),
                               base64.b64decode(data[:hlen])[:hbytes])
        raw = base64.b64decode(data[hlen:])
        buf, pos = b'', 0
        for size in header[3:]:
            buf += zlib.decompress(raw[pos:pos + size])
            pos += size
        v = np.frombuffer(buf, dtype=_VTU_TYPES[typ]).astype(float)
        out[name] = v.reshape(-1, ncomp) if ncomp > 1 else v
    return out


def read_statistics(path):
    """name -> numpy column of a statistics.txt (its "# k: name" header
    lines name the columns)."""
    names, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                names.append(line.split(':', 1)[1].strip())
            elif line.strip():
                rows.append([float(v) for v in line.split()])
    a = np.array(rows).reshape(-1, len(names))
    return {n: a[:, i] for i, n in enumerate(names)}


def read_summary(directory):
    """The summary.json of an output directory as a dict, or None if the
    run wrote none."""
    path = os.path.join(directory, 'summary.json')
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)
