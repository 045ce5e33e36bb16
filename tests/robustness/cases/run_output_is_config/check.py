assert open("config.toml").read() == "[rig]\nperiod_s = 0.001\n"
