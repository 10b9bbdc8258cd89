"""Proof for mypy that the real objects fit the protocols they are seen through: the
``ValveConnection`` fits the views' protocols (``connection_protocol.py``) and its worker's and
reconnection loop's hosts, the device layer's records fit the records a signal carries. Nothing
imports this module; it exists so that the protocol modules need not import the connection
(which imports them): no import cycle, not even under ``TYPE_CHECKING``."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from prm9tool.device.factory import DeviceEntry
    from prm9tool.device.records import DeviceInfo, UploadResult, ValveStatus
    from prm9tool.online.connection import ValveConnection
    from prm9tool.online.connection_live import LiveData
    from prm9tool.online.connection_protocol import (
        DiagramConnection,
        ParameterConnection,
        ScopeConnection,
        StatusConnection,
        StatusView,
        StepSimulation,
        UploadOutcome,
        ValveIdentity,
        ValveListing,
    )
    from prm9tool.online.connection_reconnect import ReconnectHost
    from prm9tool.online.connection_worker import LiveReports, WorkerHost
    from prm9tool.online.tuning import StepSimulator

    def _conforms(connection: ValveConnection) -> None:
        diagram: DiagramConnection = connection
        parameters: ParameterConnection = connection
        scope: ScopeConnection = connection
        status: StatusConnection = connection
        worker_host: WorkerHost = connection
        reconnect_host: ReconnectHost = connection
        del diagram, parameters, scope, status, worker_host, reconnect_host

    def _reports(live: LiveData) -> None:
        reports: LiveReports = live
        del reports

    def _records(
        info: DeviceInfo, entry: DeviceEntry, status: ValveStatus, upload: UploadResult
    ) -> None:
        identity: ValveIdentity = info
        listing: ValveListing = entry
        snapshot: StatusView = status
        outcome: UploadOutcome = upload
        del identity, listing, snapshot, outcome

    def _simulates(simulator: StepSimulator) -> None:
        simulation: StepSimulation = simulator
        del simulation
