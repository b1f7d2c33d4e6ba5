"""A sampled difference split into frequency bands (bench/reference_cases/against_converged.py --bands).

The samples must be equally spaced. The mean and the straight line through the window's ends are taken out first, so
that the window's edges do not spread a jump over every band; the rest is padded with zeros to a power of two and
transformed by a radix-2 FFT (standard library only). A band's part is the inverse transform of its frequencies alone,
so the parts of all bands add up to the signal less the line.
"""

import cmath
import math


def _fft(values, inverse=False):
    n = len(values)
    if n == 1:
        return list(values)
    even, odd = _fft(values[0::2], inverse), _fft(values[1::2], inverse)
    sign = 1 if inverse else -1
    out = [0j] * n
    for k in range(n // 2):
        twiddle = cmath.exp(sign * 2j * math.pi * k / n) * odd[k]
        out[k], out[k + n // 2] = even[k] + twiddle, even[k] - twiddle
    return out


def band_parts(times, values, edges):
    """The line through the first and last sample, and per band [edges[i], edges[i+1]) Hz (the last band open above)
    the band-limited part of values less that line, at every sample."""
    count = len(values)
    step = (times[-1] - times[0]) / (count - 1)
    line = [values[0] + (values[-1] - values[0]) * k / (count - 1) for k in range(count)]
    size = 1 << (count - 1).bit_length()
    spectrum = _fft([complex(v - l) for v, l in zip(values, line)] + [0j] * (size - count))
    parts = []
    for i, low in enumerate(edges):
        high = edges[i + 1] if i + 1 < len(edges) else math.inf
        kept = []
        for k, c in enumerate(spectrum):
            frequency = min(k, size - k) / (size * step)
            kept.append(c if low <= frequency < high else 0j)
        parts.append([z.real / size for z in _fft(kept, inverse=True)[:count]])
    return line, parts
