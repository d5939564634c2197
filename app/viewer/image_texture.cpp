#include "viewer/image_texture.h"

namespace facet::viewer {

void ImageTexture::upload(const Image& image) {
  if (image.empty()) {
    texture_ = gl::GlObject();
    framebuffer_ = gl::GlObject();
    width_ = height_ = 0;
    return;
  }
  if (!texture_ || image.width() != width_ || image.height() != height_) {
    texture_ = gl::createTexture(*gl_, GL_TEXTURE_2D);
    gl_->TextureStorage2D(texture_.id(), 1, GL_RGBA8, image.width(), image.height());
    // Linear when shrunk into a thumbnail; nearest when magnified, so pixels stay pixels.
    gl_->TextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_->TextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_->TextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_->TextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    framebuffer_ = gl::createFramebuffer(*gl_);
    gl_->NamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0);
    width_ = image.width();
    height_ = image.height();
  }
  gl_->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_->PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl_->TextureSubImage2D(texture_.id(), 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
}

}  // namespace facet::viewer
