"""Physical constants used throughout the book (SI units).

The notes use g = 9.81 m s^-2 on the Earth (it is on the 9702 data sheet) and
g = 1.62 m s^-2 on the Moon (Notes, Understand it > Weight).
"""

G_EARTH = 9.81  # m s^-2, acceleration of free fall on the Earth (= 9.81 N kg^-1)
G_MOON = 1.62  # m s^-2, acceleration of free fall on the Moon
