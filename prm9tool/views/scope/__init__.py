"""The oscilloscope window (manual §8.7.2): the widget, its plot, panels, read-outs and export."""
