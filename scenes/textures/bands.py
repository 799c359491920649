#!/usr/bin/env python3
"""An equirectangular test globe (writes bands.ppm): latitude bands every 30
degrees in alternating tints, meridians every 30 degrees in dark lines, and
a red cap on the north pole, so a sphere's orientation reads at a glance.
    python3 bands.py && convert bands.ppm bands.png
"""
W, H = 512, 256
TINTS = [(235, 225, 200), (120, 170, 210)]
with open("bands.ppm", "wb") as f:
    f.write(b"P6 %d %d 255\n" % (W, H))
    for j in range(H):
        lat = 90 - (j + 0.5) / H * 180
        for i in range(W):
            lon = (i + 0.5) / W * 360 - 180
            if lat > 75:
                c = (200, 40, 40)
            elif abs((lon + 180) % 30) < 1.2 or abs((lat + 90) % 30) < 0.8:
                c = (40, 40, 50)
            else:
                c = TINTS[int((lat + 90) // 30) % 2]
            f.write(bytes(c))
