"""The blocks of figures that benchmarks/readme_figures.py derives, one module per study."""
