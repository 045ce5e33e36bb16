assert open("precious.txt").read() == "keep me\n"
