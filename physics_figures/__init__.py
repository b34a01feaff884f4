"""Physics models and figures for the Cambridge 9702 Dynamics textbook.

Three layers, arrows pointing one way:

* ``constants`` - g and the few other constants;
* ``models``    - pure numpy physics (never imports matplotlib);
* ``figures``   - matplotlib drawings of what ``models`` computes.
"""
