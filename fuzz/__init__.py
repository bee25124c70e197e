"""Fuzz campaign of the IncirCu core: generated valid and hostile inputs, each run in a worker with a time limit.

``python -m fuzz --count 100000`` (``make fuzz N=100000``) prints the outcome table; ``python -m fuzz --seed S
--case I`` reruns one input in this process and prints it. Inputs are a pure function of ``(seed, index)``, so
any outcome can be reproduced from the two numbers the table lists.
"""
