"""Build, simulate and check the Pendulum FMU (FMI 2.0, Co-Simulation and Model Exchange)."""

__version__ = "0.1.0"
