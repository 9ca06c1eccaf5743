"""The paper's Fig. 6 from Python: its contact as creepwork fit-fig6 reproduces
it (doc/validation/paper.md), solved and printed in the paper's units, on the
rail, beside the paper's printed values."""
import creepwork

FT, LBF = 0.3048, 4.4482216152605           # the paper's units in SI
a = 0.006632269473979329  # the semi-axis creepwork fit-fig6 fits to Fx, Fy [m]
r = creepwork.solve(a=a, b=a / 2, N=10000 * LBF, mu=0.6, G=82e9, nu=0.3,
                    xi_x=0.0019, xi_y=0.0011, phi=0.144 / FT,
                    grid={"kind": "kalker_strips", "nx": 10, "ny": 10})
paper = {"Fx": 2780.880, "Fy": 3789.320, "Mz": 2.385, "Wd": 9.795, "K": 1.602}
ours = {"Fx": -r.Fx / LBF, "Fy": -r.Fy / LBF,  # on the rail = -(on the wheel)
        "Mz": -r.Mz / (LBF * FT), "Wd": r.W_macro / LBF, "K": r.K}
for key, value in ours.items():
    print("%-2s  paper %9.3f  creepwork %9.3f  %+.2f %%"
          % (key, paper[key], value, 100 * (value / paper[key] - 1)))
print("adhesion %.0f %%" % (100 * r.adhesion_fraction))
