"""lgf_fmus"""
