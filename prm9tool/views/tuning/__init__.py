"""The Tuning window: autotune, Bode, static and flow pages, their plots and the PDF report."""
