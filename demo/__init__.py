"""The demo: the script that simulates and plots every block's scenarios (python -m
demo.run_demo), with the package tools."""
