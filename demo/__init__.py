"""The demo: the Scenario class (scenarios.py) and the script that simulates and plots every block's
scenarios (python -m demo.run_demo)."""
