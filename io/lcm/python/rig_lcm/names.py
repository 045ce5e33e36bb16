"""Human names of the rig's wheels: the vehicle_state_t orders them per unit front to rear, left
before right (wheel_unit says the unit)."""


def wheel_names(wheel_units):
    """Names for the wheels of `wheel_units` (the unit of each wheel, in message order): FL, FR,
    RL, RR on a unit with two axles, A1L, A1R, A2L, ... on others; with several units each name
    starts with its unit, u0 FL, u1 A1L, ..."""
    per_unit = {}
    for unit in wheel_units:
        per_unit[unit] = per_unit.get(unit, 0) + 1
    several = len(per_unit) > 1
    seen = {}
    names = []
    for unit in wheel_units:
        k = seen.get(unit, 0)
        seen[unit] = k + 1
        side = "LR"[k % 2]
        if per_unit[unit] == 4:
            name = ("F" if k < 2 else "R") + side
        else:
            name = f"A{k // 2 + 1}{side}"
        names.append(f"u{unit} {name}" if several else name)
    return names
