"""The physical limits a scene is held to (:mod:`cosim.scene.plausible`, and the ranges of
the fields in :mod:`cosim.scene.spec`), each with the reason for its value. A value beyond
one is not a scene of this world: a unit slip (millimetres for metres, g for m/s^2), a
number typed in the wrong field, or a number meant to break the run. Each limit is well
outside what real structures, materials and experiments reach, so that no real scene is
refused by it; each message states the limit and why.
"""

from __future__ import annotations

#: standard gravity [m/s^2] (the unit "g" of accelerograms and of the limits below)
G0 = 9.80665

#: the strongest gravity a scene may have [m/s^2]: 100 g, a geotechnical centrifuge's range
MAX_GRAVITY = 100 * G0
GRAVITY_WHY = "100 g, the most a geotechnical centrifuge applies to a model (Earth: 9.81)"

#: the densest matter at rest [kg/m^3]: osmium; any body, plate or liquid is lighter
MAX_DENSITY = 22_590.0
DENSITY_WHY = "osmium's, the densest element (steel 7850, mercury 13 546)"

#: the stiffest material [Pa]: diamond
MAX_YOUNG = 1.2e12
YOUNG_WHY = "diamond's, the stiffest material (steel 2.1e11)"

#: a mooring line's largest submerged weight per length [N/m]: ten times the heaviest
#: offshore chain's (220 mm studless, about 8.6 kN/m submerged)
MAX_LINE_WEIGHT = 1e5
LINE_WEIGHT_WHY = "ten times the heaviest offshore chain's (220 mm, about 8.6 kN/m submerged)"

#: a mooring line's largest mass per length [kg/m]: ten times that chain's (about 1 t/m)
MAX_LINE_MASS = 1e4
LINE_MASS_WHY = "ten times the heaviest offshore chain's (220 mm, about 1000 kg/m)"

#: a mooring line's largest axial stiffness [N]: four times a tension-leg platform's steel
#: tendon (1 m across, 40 mm wall: about 2.6e10 N)
MAX_LINE_EA = 1e11
LINE_EA_WHY = "four times a tension-leg platform's steel tendon (about 2.6e10 N)"

#: a mooring line's largest hydrodynamic diameter [m]
MAX_LINE_DIAMETER = 10.0
LINE_DIAMETER_WHY = "ten times the widest riser's"

#: the largest breaking load [N]: ten times the strongest chain's (220 mm R5, about 3e7 N)
MAX_BREAK_LOAD = 3e8
BREAK_LOAD_WHY = "ten times the strongest chain's (220 mm R5, about 3e7 N)"

#: the largest strain an elastic line may start at [-]: beyond the breaking strain of
#: every mooring material (steel about 2 %, polyester 12 %, nylon about 25 %)
MAX_LINE_STRAIN = 0.3

#: the largest peak acceleration of a tank's base motion [m/s^2]: 5 g, above the strongest
#: shaking tables' and recorded earthquakes' peaks (about 3-4 g)
MAX_BASE_ACCELERATION = 5 * G0

#: the fastest a body may start [m/s]: above the fastest water entries these models are used
#: for (an aircraft ditching, about 70 m/s; a free-fall lifeboat, 25-30 m/s)
MAX_BODY_SPEED = 100.0
BODY_SPEED_WHY = "above the fastest water entries these models serve (an aircraft ditching, about 70 m/s)"

#: how far from its centre a body's fairlead may lie, in bounding radii of the body [-]
#: (its hull and a short arm: a fairlead further out is not on the body)
FAIRLEAD_REACH = 1.5

#: the largest share of a flume's length the paddle may sweep forward (half its stroke) [-]
PADDLE_SHARE = 0.25

#: the largest length or coordinate [m]: the Earth's radius (a scene lies on the Earth)
MAX_LENGTH = 6.371e6
#: the smallest size [m] of anything a scene declares > 0: a micron, below which the water
#: around a body is no continuum for these models
MIN_LENGTH = 1e-6
#: the lightest matter a body, plate or liquid may be [kg/m^3]: a tenth of air's density
MIN_DENSITY = 0.1
