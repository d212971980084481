"""core/plan_job: planning on a thread of its own, as the Plan operator runs
it in Blender's interface: the same plan, progress, cancelling, errors."""

import pathlib
import time

import pytest

from footfall.core.plan_job import PlanJob
from footfall.core.scenario import document_of, plan

STEERSUITE = pathlib.Path(__file__).resolve().parents[1] / "data" / "steersuite"


def test_a_job_plans_what_planning_at_once_plans(ff):
    document = document_of(ff.demo_scenario())
    job = PlanJob(document, threads=2)
    result = job.result()
    assert job.done and not job.cancelled and job.progress == 1.0 and job.seconds > 0
    assert ff.plan_to_json(result) == ff.plan_to_json(plan(document))


def test_a_cancelled_job_stops_and_says_so(ff):
    document = document_of(ff.load_steersuite(str(STEERSUITE / "bottleneck-evacuation.xml")))
    job = PlanJob(document, threads=1)
    deadline = time.monotonic() + 30
    while job.progress == 0.0 and not job.done and time.monotonic() < deadline:
        time.sleep(0.01)
    job.cancel()
    result = job.result()
    assert job.cancelled and result.status == ff.Status.CANCELLED
    assert any(agent.reason == "cancelled" for agent in result.agents)


def test_an_error_reaches_the_caller(ff):
    document = document_of(ff.demo_scenario())
    document["agents"][0]["position"] = [float("nan"), 0.0]
    job = PlanJob(document, threads=1)
    with pytest.raises(ValueError, match=r"scene: agents\[0\].position\[0\]: must be a finite number"):
        job.result()
