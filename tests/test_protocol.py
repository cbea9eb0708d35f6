"""The coupler's roles and hooks (cosim.protocol): the solvers offer what the coupler tests
for, under the names it tests for (a renamed hook would be skipped without a word), and a
participant that claims a role without filling it is refused before the run."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import ProtocolError
from cosim.protocol import (AddedMassLoads, Breaking, DrivenBodies, DrivenToStepEnd, DynamicMooring, ElasticStructures,
                            ExchangedLoads, Fluid, LimitReported, LineStiffness, Mooring, Participant, Tethered,
                            TimedLoads, protocol_members)
from fluid.analytic import AnalyticFluid
from moorings import MooringLine
from moorings.catenary_mooring import CatenaryMooring


def _offers(cls, protocol) -> list[str]:
    """The members of ``protocol`` beyond the participant's own that ``cls`` lacks (its
    methods, properties and class attributes)."""
    own = protocol_members(Mooring if Mooring in protocol.__mro__ else Participant)
    return sorted(m for m in protocol_members(protocol) - own if not hasattr(cls, m))


def _classes():
    from cosim.sph_fluid import SPHFluid
    from fluid.potential import PotentialFluid
    from moorings.breaking import BreakingMooring
    from moorings.fmu_mooring import FMUMooring
    from moorings.moordyn_mooring import MoorDynMooring
    from moorings.sph_cable import SPHCableMooring

    return [(SPHFluid, [Fluid, ExchangedLoads, ElasticStructures, LimitReported]),
            (AnalyticFluid, [Fluid, TimedLoads, AddedMassLoads]),
            (PotentialFluid, [Fluid, TimedLoads]),
            (MujocoBodies, [DrivenBodies]),
            (CatenaryMooring, [Tethered, LineStiffness]),
            (SPHCableMooring, [DynamicMooring, LineStiffness]),
            (MoorDynMooring, [DynamicMooring, DrivenToStepEnd, LineStiffness]),
            (FMUMooring, [LineStiffness]),
            (BreakingMooring, [Breaking, Tethered])]


@pytest.mark.parametrize("cls, roles", _classes(), ids=lambda x: getattr(x, "__name__", ""))
def test_the_solvers_offer_the_hooks_the_coupler_tests_for(cls, roles):
    for protocol in roles:
        assert not _offers(cls, protocol), f"{cls.__name__} lacks {_offers(cls, protocol)} of {protocol.__name__}"


def _box():
    return MujocoBodies(builders.scene(builders.box("b", (1.0, 1.0), (0, 0, 0), density=500.0, planar=True)))


def test_a_fluid_without_its_loads_is_refused_naming_them():
    class Mute:  # a participant that takes the bodies but gives no loads
        name = "mute"

        def initialize(self, t0):
            pass

        def max_dt(self):
            return math.inf

        def advance(self, t, dt):
            pass

        def save_state(self):
            return {}

        def load_state(self, state):
            pass

        def attach_bodies(self, bodies):
            pass

        def set_body_kinematics(self, kinematics):
            pass

    with pytest.raises(ProtocolError, match="cannot act as a Fluid: it lacks body_wrenches"):
        Coupler(bodies=_box(), fluid=Mute())


def test_a_mooring_that_says_it_is_dynamic_must_report_its_mean_force():
    class Claims(CatenaryMooring):
        dynamic = True  # but no mean_fairlead_forces()

    line = MooringLine(np.array([5.0, -5.0]), 10.0, 10.0, EA=1e6, name="l")
    b = MujocoBodies(builders.scene(builders.box("b", (1.0, 1.0), (0, 0, 0), density=500.0, planar=True,
                                                 sites={"fl": (0.5, 0.0, 0.0)})))
    with pytest.raises(ProtocolError, match="cannot act as a DynamicMooring: it lacks mean_fairlead_forces"):
        Coupler(bodies=b, moorings=[(Claims([line]), ["fl"])])
