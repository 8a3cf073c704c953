# Reads the binary (base64) DataArrays of this project's snapshots into lists: a .vtu,
# or a .pvtu (a run over several MPI ranks) with the pieces it lists joined in order.
import re, base64, struct, sys, math, os
def snapshots(run):
    """The snapshot files of run directory `run` in time order, as run.pvd lists them
    (.vtu, or .pvtu for a run over several MPI ranks, whose pieces are not listed)."""
    pvd = open(os.path.join(run, 'run.pvd')).read()
    return [os.path.join(run, f) for f in re.findall(r'file="([^"]+)"', pvd)]
def read(path):
    s = open(path).read()
    if path.endswith('.pvtu'):
        out = {}
        for source in re.findall(r'<Piece Source="([^"]+)"/>', s):
            for name, vals in read(os.path.join(os.path.dirname(path), source)).items():
                out.setdefault(name, []).extend(vals)
        return out
    out = {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="binary">\s*([A-Za-z0-9+/=]+)\s*</DataArray>', s):
        t, name, nc, data = m.group(1), m.group(2), int(m.group(3)), m.group(4)
        raw = base64.b64decode(data)
        n = struct.unpack('<Q', raw[:8])[0]
        fmt = {'Float64': 'd', 'UInt16': 'H', 'UInt64': 'Q', 'Int64': 'q', 'UInt8': 'B'}[t]
        size = struct.calcsize(fmt)
        vals = struct.unpack('<%d%s' % (n // size, fmt), raw[8:8 + n])
        out[name] = [vals[i*nc:(i+1)*nc] for i in range(len(vals)//nc)] if nc > 1 else list(vals)
    return out
