"""fractal"""
