# Reads the binary (base64) DataArrays of this project's .vtu snapshots into lists.
import re, base64, struct, sys, math
def read(path):
    s = open(path).read()
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
